// imasim: real-time simulator for robotic internal mammary artery harvesting.
#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <vector>

#include "commands.hpp"
#include "spawn_self.hpp"

int main(int argc, char** argv) {
  imasim::cli::die_with_parent();
  CLI::App app{"imasim: robotic IMA harvesting simulator"};
  const imasim::cli::Commands commands = imasim::cli::add_commands(app);
  // No subcommand: the window on the default scene where there is a display, else how to run
  // headless.
  std::vector<char*> args(argv, argv + argc);
  char window[] = "window";
  if (argc == 1) {
    if (!imasim::cli::display_available()) {
      imasim::cli::print_headless_hint(std::cerr);
      return 2;
    }
    args.push_back(window);
  }
  try {
    app.parse(static_cast<int>(args.size()), args.data());
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  } catch (const std::exception& e) {  // e.g. out of memory while parsing the arguments
    std::cerr << "imasim: error: " << e.what() << '\n';
    return 2;
  }
  try {
    return imasim::cli::run_chosen_command(app, commands);
  } catch (const std::exception& e) {
    std::cerr << "imasim: error: " << e.what() << '\n';
    return 2;
  } catch (...) {  // the last resort: every known failure has its own message
    std::cerr << "imasim: error: an unexpected failure (not a standard exception)\n";
    return 2;
  }
}
