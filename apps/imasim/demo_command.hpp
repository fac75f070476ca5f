#pragma once
// `imasim demo [--trials N] [--out DIR] [--jobs J]`: the main job. The built-in scene, headless,
// the scripted operator harvesting with the beating and with the static heart (N trials each,
// default 3), the progress bar, then a short summary on the terminal and the report's path.
#include <CLI/CLI.hpp>
#include <memory>

#include "study_run.hpp"

namespace imasim::cli {

struct DemoOptions {
  StudyRequest request;
};

std::shared_ptr<DemoOptions> add_demo_command(CLI::App& app);
int run_demo_command(const DemoOptions& options);

}  // namespace imasim::cli
