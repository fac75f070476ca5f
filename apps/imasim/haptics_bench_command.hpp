#pragma once
// `imasim haptics-bench --seconds T [--script FILE] [--json]`: the 1 kHz haptic loop measured
// while the default scene runs in real time, driven end to end as `imasim run --devices
// emulator` drives it (live_inputs.hpp). Three threads and a second process:
//   physics (this thread): the surgical session stepped every 5 ms of wall-clock time,
//     publishing each instrument's local model lock-free;
//   haptics (LiveConsole, 1 kHz): reads the devices' poses from OpenIGTLink on loopback,
//     evaluates eq. 17-19 against the newest local model, filters through the safety layer and
//     sends each hand its force;
//   devices: `imasim device-emulator --loop` playing the example script on two emulated
//     desktop haptic devices (a mass-spring-damper per hand, 1 kHz) that apply the force they
//     receive.
// Prints the loop's figures; with --json exactly: rate_hz, period_p50_us, period_p99_error_us,
// period_max_us, missed_deadlines, latency_p99_us, force_max_n, contacts.
#include <CLI/CLI.hpp>
#include <memory>
#include <string>

namespace imasim::cli {

struct HapticsBenchOptions {
  double seconds = 10;
  std::string script_file;  // empty: the built-in example script (example_script.hpp)
  bool json = false;
};

std::shared_ptr<HapticsBenchOptions> add_haptics_bench_command(CLI::App& app);
int run_haptics_bench_command(const HapticsBenchOptions& options);

}  // namespace imasim::cli
