#include "heatmap_command.hpp"

#include <iostream>
#include <nlohmann/json.hpp>

#include "cli_checks.hpp"
#include "metrics/heat_map.hpp"
#include "metrics/output_file.hpp"
#include "metrics/point_csv.hpp"
#include "report.hpp"

namespace imasim::cli {

std::shared_ptr<HeatmapOptions> add_heatmap_command(CLI::App& app) {
  auto opt = std::make_shared<HeatmapOptions>();
  CLI::App* cmd = app.add_subcommand(
      "heatmap", "Heat map (Fig. 13) of the tool tips of one or more recordings, as PNG");
  cmd->add_option("--trajectory", opt->trajectories,
                  "CSV of tool tips (repeat to pool recordings): header t,x,y,z, or the "
                  "recorder's file with --tool (m)")
      ->required()
      ->check(non_empty());
  cmd->add_option("--tool", opt->tool, "In the recorder's files, the instrument whose tips to draw")
      ->check(CLI::IsMember({"forceps", "hook"}));
  cmd->add_option("--frame", opt->frame, "The plane and anatomy: a recording's FILE.frame.json")
      ->required()
      ->check(non_empty());
  cmd->add_option("--out", opt->out, "The PNG to write")->required()->check(non_empty());
  cmd->add_option("--title", opt->title, "Title (default: says what is drawn)");
  cmd->add_option("--subtitle", opt->subtitle, "Second line under the title (e.g. the SAI)");
  cmd->add_option("--bandwidth", opt->bandwidth, "Gaussian kernel's standard deviation (m)")
      ->capture_default_str()
      ->check(finite_range(1e-5, 0.05));
  cmd->add_option("--density-max", opt->density_max,
                  "Top of the colour scale, share of samples per mm^2 (0: the map's maximum; give "
                  "maps to be compared the same)")
      ->capture_default_str()
      ->check(finite_range(0, 1e6));
  cmd->add_option("--width", opt->width, "Picture width (px)")
      ->capture_default_str()
      ->check(CLI::Range(480, 8000));
  cmd->add_option("--height", opt->height, "Picture height (px)")
      ->capture_default_str()
      ->check(CLI::Range(360, 8000));
  cmd->add_flag("--json", opt->json, "Print one JSON object on stdout");
  return opt;
}

int run_heatmap_command(const HeatmapOptions& o) {
  std::vector<Vec3> tips;
  metrics::HeatMapFrame frame;
  try {
    for (const std::string& path : o.trajectories) {
      const metrics::PointSeries series = metrics::load_trajectory_csv(path, o.tool);
      tips.insert(tips.end(), series.points.begin(), series.points.end());
    }
    frame = metrics::read_heat_map_frame(o.frame);
  } catch (const metrics::PointCsvError& e) {
    std::cerr << "imasim heatmap: " << e.what() << '\n';
    return 2;
  } catch (const metrics::HeatMapFrameError& e) {
    std::cerr << "imasim heatmap: " << e.what() << '\n';
    return 2;
  }
  metrics::HeatMapStyle style;
  const std::string recordings = std::to_string(o.trajectories.size()) +
                                 (o.trajectories.size() == 1 ? " recording" : " recordings");
  style.title = !o.title.empty() ? o.title
                : o.tool.empty() ? "Tool-tip density"
                                 : "Tool-tip density: " + o.tool;
  style.subtitle = !o.subtitle.empty() ? o.subtitle : recordings + " pooled";
  style.bandwidth = o.bandwidth;
  style.density_max = o.density_max;
  style.width = o.width;
  style.height = o.height;
  metrics::DensityGrid drawn;
  try {
    std::vector<std::string> all_inputs = o.trajectories;
    all_inputs.push_back(o.frame);
    drawn = metrics::write_heat_map_png(frame, tips, style, o.out, all_inputs);
  } catch (const metrics::OutputError& e) {
    std::cerr << "imasim heatmap: " << e.what() << '\n';
    return 4;
  } catch (const std::invalid_argument& e) {
    std::cerr << "imasim heatmap: " << e.what() << '\n';
    return 2;
  }
  nlohmann::ordered_json out;
  out["png"] = o.out;
  out["samples"] = drawn.samples;
  out["recordings"] = o.trajectories.size();
  out["density_max_per_mm2"] = o.density_max > 0 ? o.density_max : drawn.max;
  return print_report(out, o.json) ? 0 : 4;
}

}  // namespace imasim::cli
