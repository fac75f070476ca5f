#include "sai_command.hpp"

#include <iostream>
#include <nlohmann/json.hpp>

#include "cli_checks.hpp"
#include "metrics/point_csv.hpp"
#include "metrics/spatial_asymmetry.hpp"
#include "report.hpp"
#include "scene/mesh_file.hpp"

namespace imasim::cli {

std::shared_ptr<SaiOptions> add_sai_command(CLI::App& app) {
  auto opt = std::make_shared<SaiOptions>();
  CLI::App* cmd = app.add_subcommand(
      "sai", "Spatial Asymmetry Index (eq. 20) of a tool's trajectory beside the IMA");
  cmd->add_option("--trajectory", opt->trajectory,
                  "CSV of tool tips: header t,x,y,z, or the recorder's file with --tool (m)")
      ->required()
      ->check(non_empty());
  cmd->add_option("--centerline", opt->centerline, "CSV of the IMA centerline: header x,y,z (m)")
      ->required()
      ->check(non_empty());
  cmd->add_option("--heart", opt->heart, "The heart's surface mesh at the sampled phase")
      ->required()
      ->check(non_empty());
  cmd->add_option("--radius", opt->radius, "R of eq. 20 (m)")
      ->capture_default_str()
      ->check(finite_range(1e-6, 1));
  cmd->add_option(
         "--tool", opt->tool,
         "In the recorder's file (time t_s), the tool whose columns NAME_x, NAME_y, NAME_z to use")
      ->check(non_empty());
  cmd->add_option("--heart-scale", opt->heart_scale, "Heart mesh units to m (0.001: mm)")
      ->capture_default_str()
      ->check(finite_range(1e-6, 1e3));
  cmd->add_flag("--json", opt->json, "Print one JSON object on stdout");
  return opt;
}

int run_sai_command(const SaiOptions& o) {
  metrics::SaiResult r;
  try {
    const metrics::PointSeries tips = metrics::load_trajectory_csv(o.trajectory, o.tool);
    // Eq. 20 is a mean over the samples: of none it is undefined, not 0.
    if (tips.points.empty()) {
      std::cerr << "imasim sai: " << o.trajectory
                << ": the trajectory has no samples (a header only): eq. 20's mean of nothing is "
                   "no score\n";
      return 2;
    }
    const metrics::PointSeries centerline = metrics::load_centerline_csv(o.centerline);
    scene::MeshLoadOptions mesh;
    mesh.transform.scale = Real(o.heart_scale);
    mesh.run_checks = false;  // only nearest points are needed: any triangles will do
    const geometry::TriangleMesh heart = scene::load_mesh_file(o.heart, mesh);
    const metrics::SideReference side = metrics::make_side_reference(centerline.points, heart);
    r = metrics::spatial_asymmetry(side, tips.points, Real(o.radius));
  } catch (const metrics::PointCsvError& e) {
    std::cerr << "imasim sai: " << e.what() << '\n';
    return 2;
  } catch (const scene::MeshFileError& e) {
    std::cerr << "imasim sai: " << e.what() << '\n';
    return 2;
  } catch (const metrics::SaiError& e) {
    std::cerr << "imasim sai: " << e.what() << '\n';
    return 2;
  }
  nlohmann::ordered_json out;
  out["sai"] = r.sai;
  out["samples"] = r.samples;
  out["mean_distance_m"] = r.mean_distance;
  out["heart_side_fraction"] = r.heart_side_fraction;
  return print_report(out, o.json) ? 0 : 4;
}

}  // namespace imasim::cli
