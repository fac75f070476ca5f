#pragma once
// `imasim press --tissue fascia|fat|ima|heart|wall [--depth-mm LIST] [--hold-s S] [--scene FILE]
// [--json]`: the cautery hook pressed into one tissue of the scene, held and settled at each depth
// past its resting surface (console/press_probe.hpp), and the force the device receives beside the
// force table's k_d d (eq. 17). Prints {"tissue": ..., "k_d_n_per_m": ..., "depths": [{"depth_mm":
// ..., "force_n": ..., "law_n": ..., "ratio": ...}, ...]}.
#include <CLI/CLI.hpp>
#include <memory>
#include <string>
#include <vector>

#include "console/press_probe.hpp"

namespace imasim::cli {

struct PressOptions {
  std::string tissue, scene_file;
  std::vector<double> depths_mm = {1, 2, 3, 4, 5};
  double hold_s = console::PressSettings{}.settle_s;
  int threads = 1;
  bool json = false;
};

std::shared_ptr<PressOptions> add_press_command(CLI::App& app);
int run_press_command(const PressOptions& options);

}  // namespace imasim::cli
