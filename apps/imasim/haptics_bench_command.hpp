#pragma once
// `imasim haptics-bench --seconds T [--json]`: the 1 kHz haptic loop measured while the default
// scene runs in real time. Three threads, as the interactive simulator will have them:
//   physics (this thread): the example surgical session stepped every 5 ms of wall-clock time,
//     publishing each instrument's local model (its contacts, tissue, cautery) lock-free;
//   haptics (HapticLoop, 1 kHz): reads the emulated devices' poses from an OpenIGTLink link on
//     loopback, evaluates eq. 17-19 against the newest local model, filters through the safety
//     layer and sends each hand its force;
//   devices: two emulated desktop haptic devices (a mass-spring-damper per hand, 1 kHz) that
//     follow the instruments' tips and apply the force they receive, over OpenIGTLink.
// Prints the loop's figures; with --json exactly: rate_hz, period_p50_us, period_p99_error_us,
// period_max_us, missed_deadlines, latency_p99_us, force_max_n, contacts.
#include <CLI/CLI.hpp>
#include <memory>

namespace imasim::cli {

struct HapticsBenchOptions {
  double seconds = 10;
  bool json = false;
};

std::shared_ptr<HapticsBenchOptions> add_haptics_bench_command(CLI::App& app);
int run_haptics_bench_command(const HapticsBenchOptions& options);

}  // namespace imasim::cli
