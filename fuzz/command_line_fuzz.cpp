// libFuzzer target: the command line. The bytes are split into arguments at NUL bytes (at most
// kMaxArguments) and parsed as `imasim ARGS...` is: every subcommand, option and validator of
// the real program. Any arguments are either refused with a CLI11 parse error (a message, exit
// code 2 or the help's 0) or accepted with values inside the documented ranges; nothing is run.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

#include "commands.hpp"
#include "console/press_probe.hpp"
#include "fuzz_check.hpp"
#include "metrics/trainee_name.hpp"

namespace {

constexpr std::size_t kMaxArguments = 64;

std::vector<std::string> split_arguments(const std::uint8_t* data, std::size_t size) {
  std::vector<std::string> args{"imasim"};
  std::string current;
  for (std::size_t i = 0; i < size && args.size() < kMaxArguments; ++i) {
    if (data[i] == 0) {
      args.push_back(current);
      current.clear();
    } else {
      current.push_back(static_cast<char>(data[i]));
    }
  }
  if (!current.empty() && args.size() < kMaxArguments) args.push_back(current);
  return args;
}

void check_run_options(const imasim::cli::RunOptions& o) {
  using imasim::fuzz::require;
  require(std::isfinite(o.seconds) && o.seconds >= 0, "run --seconds accepted out of range");
  require(o.heart_rate_bpm == 0 || (o.heart_rate_bpm >= 20 && o.heart_rate_bpm <= 250),
          "run --heart-rate accepted out of range");
  require(o.repeat >= 1, "run --repeat accepted below 1");
  require(o.threads >= 0 && o.threads <= 1024, "run --threads accepted out of range");
  require(o.trainee.empty() || imasim::metrics::trainee_name_problem(o.trainee).empty(),
          "run --trainee accepted a name the records refuse");
  require(!(o.no_db && !o.db_file.empty()), "run --no-db accepted with --db");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::vector<std::string> args = split_arguments(data, size);
  std::vector<const char*> argv;
  for (const std::string& a : args)
    argv.push_back(a.c_str());
  // The program main() parses (apps/imasim/commands.hpp).
  CLI::App app{"imasim: robotic IMA harvesting simulator"};
  const imasim::cli::Commands commands = imasim::cli::add_commands(app);
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::ParseError& e) {
    std::ostringstream out, err;
    const int code = app.exit(e, out, err);
    imasim::fuzz::require(code == 0 || !err.str().empty() || !out.str().empty(),
                          "a refused command line with no message");
    return 0;
  }
  if (app.got_subcommand("run")) check_run_options(*commands.run);
  if (app.got_subcommand("history")) {
    const std::string& trainee = commands.history->trainee;
    imasim::fuzz::require(trainee.empty() || imasim::metrics::trainee_name_problem(trainee).empty(),
                          "history --trainee accepted a name the records refuse");
  }
  if (app.got_subcommand("haptics-bench")) {
    const double seconds = commands.haptics_bench->seconds;
    imasim::fuzz::require(std::isfinite(seconds) && seconds >= 0.1 && seconds <= 3600,
                          "haptics-bench --seconds accepted out of range");
  }
  if (app.got_subcommand("heatmap")) {
    const imasim::cli::HeatmapOptions& h = *commands.heatmap;
    imasim::fuzz::require(std::isfinite(h.bandwidth) && h.bandwidth >= 1e-5 && h.bandwidth <= 0.05,
                          "heatmap --bandwidth accepted out of range");
    imasim::fuzz::require(std::isfinite(h.density_max) && h.density_max >= 0,
                          "heatmap --density-max accepted out of range");
    imasim::fuzz::require(h.width >= 480 && h.width <= 8000 && h.height >= 360 && h.height <= 8000,
                          "heatmap --width or --height accepted out of range");
  }
  if (app.got_subcommand("press")) {
    const imasim::cli::PressOptions& p = *commands.press;
    for (const double mm : p.depths_mm)
      imasim::fuzz::require(std::isfinite(mm) && mm >= 0.01 && mm <= 15,
                            "press --depth-mm accepted out of range");
    imasim::fuzz::require(imasim::console::press_tissue_named(p.tissue).has_value(),
                          "press --tissue accepted an unknown tissue");
  }
  return 0;
}
