#pragma once
// `imasim sai --trajectory T.csv --centerline C.csv --heart H.obj [--radius R] [--tool NAME]
// [--heart-scale S] [--json]`: the Spatial Asymmetry Index of one tool's trajectory (eq. 20,
// metrics/spatial_asymmetry.hpp): sai, samples, mean_distance_m, heart_side_fraction. T.csv is
// the recorder's file (with --tool, its columns t_s, NAME_x, NAME_y, NAME_z) or a plain CSV with
// the header t,x,y,z; C.csv has the header x,y,z; H.obj is the heart's surface at the sampled phase
// (any format the mesh loader reads); all in metres unless --heart-scale says otherwise.
#include <CLI/CLI.hpp>
#include <memory>
#include <string>

namespace imasim::cli {

struct SaiOptions {
  std::string trajectory, centerline, heart, tool;
  double radius = 0.002;
  double heart_scale = 1;
  bool json = false;
};

std::shared_ptr<SaiOptions> add_sai_command(CLI::App& app);
int run_sai_command(const SaiOptions& options);

}  // namespace imasim::cli
