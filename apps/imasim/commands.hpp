#pragma once
// Every subcommand of `imasim`, registered in one place: main() and the command-line fuzz target
// (fuzz/command_line_fuzz.cpp) parse exactly the same program.
#include <CLI/CLI.hpp>
#include <memory>

#include "cloth_command.hpp"
#include "demo_command.hpp"
#include "device_emulator_command.hpp"
#include "devices_command.hpp"
#include "experiment_command.hpp"
#include "haptics_bench_command.hpp"
#include "heatmap_command.hpp"
#include "history_command.hpp"
#include "press_command.hpp"
#include "render_command.hpp"
#include "run_command.hpp"
#include "sai_command.hpp"
#include "scene_command.hpp"
#include "stats_command.hpp"
#include "window_command.hpp"

namespace imasim::cli {

struct Commands {
  std::shared_ptr<ClothOptions> cloth;
  std::shared_ptr<RunOptions> run;
  std::shared_ptr<SceneOptions> scene;
  std::shared_ptr<HapticsBenchOptions> haptics_bench;
  std::shared_ptr<DeviceEmulatorOptions> device_emulator;
  std::shared_ptr<DevicesOptions> devices;
  std::shared_ptr<StatsOptions> stats;
  std::shared_ptr<SaiOptions> sai;
  std::shared_ptr<HeatmapOptions> heatmap;
  std::shared_ptr<HistoryOptions> history;
  std::shared_ptr<PressOptions> press;
  std::shared_ptr<ExperimentOptions> experiment;
  std::shared_ptr<DemoOptions> demo;
  std::shared_ptr<RenderOptions> render;
  std::shared_ptr<WindowCommandOptions> window;
};

// Registers every subcommand on `app` (one is required).
Commands add_commands(CLI::App& app);

// Runs the subcommand the parsed command line chose; returns the process's exit code.
int run_chosen_command(const CLI::App& app, const Commands& commands);

}  // namespace imasim::cli
