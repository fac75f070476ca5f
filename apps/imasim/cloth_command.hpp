#pragma once
// `imasim cloth`: runs the cloth verification scene and prints its summary.
#include <CLI/CLI.hpp>
#include <memory>

#include "scene/cloth_scene.hpp"

namespace imasim::cli {

struct ClothOptions {
  scene::ClothParams params;
  std::uint32_t steps = 400;
  int threads = 0;               // 0 = all cores
  std::vector<Real> pbd;         // KDIST,KBEND
  std::vector<Real> compliance;  // ADIST,ABEND
  bool json = false;
};

// Registers the subcommand; the returned options are filled when the command line is parsed.
std::shared_ptr<ClothOptions> add_cloth_command(CLI::App& app);

// Runs the scene; returns the process exit code (0 ok, 3 the simulation diverged).
int run_cloth_command(const ClothOptions& options);

}  // namespace imasim::cli
