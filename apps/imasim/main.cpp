// imasim: real-time simulator for robotic internal mammary artery harvesting.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>

#include "cloth_command.hpp"
#include "haptics_bench_command.hpp"
#include "run_command.hpp"
#include "scene_command.hpp"

int main(int argc, char** argv) {
  CLI::App app{"imasim: robotic IMA harvesting simulator"};
  app.require_subcommand(1);
  auto cloth = imasim::cli::add_cloth_command(app);
  auto run = imasim::cli::add_run_command(app);
  auto scene = imasim::cli::add_scene_command(app);
  auto haptics_bench = imasim::cli::add_haptics_bench_command(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {  // e.g. out of memory while parsing the arguments
    std::cerr << "imasim: error: " << e.what() << '\n';
    return 2;
  }
  try {
    if (app.got_subcommand("cloth")) return imasim::cli::run_cloth_command(*cloth);
    if (app.got_subcommand("run")) return imasim::cli::run_run_command(*run);
    if (app.got_subcommand("scene")) return imasim::cli::run_scene_command(*scene);
    if (app.got_subcommand("haptics-bench"))
      return imasim::cli::run_haptics_bench_command(*haptics_bench);
  } catch (const std::exception& e) {
    std::cerr << "imasim: error: " << e.what() << '\n';
    return 2;
  } catch (...) {  // the last resort: every known failure has its own message
    std::cerr << "imasim: error: an unexpected failure (not a standard exception)\n";
    return 2;
  }
  return 0;
}
