#include "press_command.hpp"

#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli_checks.hpp"
#include "command_inputs.hpp"
#include "console/press_probe.hpp"
#include "report.hpp"

namespace imasim::cli {

std::shared_ptr<PressOptions> add_press_command(CLI::App& app) {
  auto opt = std::make_shared<PressOptions>();
  CLI::App* cmd = app.add_subcommand(
      "press", "Press the hook into a tissue and compare the force felt with k_d d (eq. 17)");
  cmd->add_option("--tissue", opt->tissue, "fascia, fat, ima, heart or wall")
      ->required()
      ->check(CLI::IsMember({"fascia", "fat", "ima", "heart", "wall"}));
  cmd->add_option("--depth-mm", opt->depths_mm,
                  "Depths past the resting surface, each held and settled (mm)")
      ->delimiter(',')
      ->capture_default_str()
      ->check(finite_range(0.01, 15));
  cmd->add_option("--hold-s", opt->hold_s,
                  "Held at each depth before the force is read, its last 0.1 s averaged (s)")
      ->capture_default_str()
      ->check(finite_range(0.2, 60));
  cmd->add_option("--scene", opt->scene_file, "Scene file (TOML); default: the built-in scene")
      ->check(non_empty());
  cmd->add_option("--threads", opt->threads, "Worker threads (0 = all cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, 256));
  cmd->add_flag("--json", opt->json, "Print one JSON object on stdout");
  return opt;
}

int run_press_command(const PressOptions& o) {
  scene::ThoraxSceneParams params;
  if (!load_scene_params(o.scene_file, params)) return 2;
  const console::PressTissue tissue = *console::press_tissue_named(o.tissue);
  std::vector<double> depths;
  for (const double mm : o.depths_mm)
    depths.push_back(mm * 1e-3);
  physics::Executor exec(o.threads);
  console::PressSettings settings;
  settings.settle_s = o.hold_s;
  console::PressResult r;
  try {
    r = console::press_tissue(params, tissue, depths, settings, exec);
  } catch (const std::exception& e) {
    std::cerr << "imasim press: " << e.what() << '\n';
    return 2;
  }
  auto round6 = [](double v) { return std::round(v * 1e6) / 1e6; };
  nlohmann::ordered_json out;
  out["tissue"] = console::press_tissue_name(r.tissue);
  out["k_d_n_per_m"] = r.k_d;
  out["site_m"] = {round6(r.site.x()), round6(r.site.y()), round6(r.site.z())};
  out["normal"] = {round6(r.normal.x()), round6(r.normal.y()), round6(r.normal.z())};
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const console::PressPoint& p : r.points) {
    nlohmann::ordered_json row;
    row["depth_mm"] = round6(p.depth_m * 1e3);
    row["force_n"] = p.force_n;
    row["law_n"] = p.law_n;
    row["ratio"] = p.law_n > 0 ? p.force_n / p.law_n : 0.0;
    row["force_along_press_n"] = p.force_along_press_n;
    row["tool_depth_mm"] = round6(p.proxy_depth_m * 1e3);
    rows.push_back(row);
  }
  out["depths"] = rows;
  out["steps"] = r.steps;
  return print_report(out, o.json) ? 0 : 4;
}

}  // namespace imasim::cli
