#include "haptics_bench_command.hpp"

#include <algorithm>
#include <chrono>
#include <iostream>
#include <nlohmann/json.hpp>
#include <thread>

#include "cli_checks.hpp"
#include "haptics/haptic_loop.hpp"
#include "interrupt.hpp"
#include "live_inputs.hpp"
#include "physics/executor.hpp"
#include "runner/session_runner.hpp"
#include "scene/thorax_scene.hpp"
#include "session/surgical_session.hpp"

namespace imasim::cli {

namespace {

// The machine's floor: the same 1 kHz schedule (sleep, then spin to the deadline, at the same
// real-time priority) with nothing to do in a tick, for `seconds`. What it misses is the
// machine's, not the loop's.
haptics::HapticLoopStats bare_sleeper(double seconds) {
  haptics::HapticLoop loop(haptics::HapticLoopConfig{}, [](double) {});
  loop.start();
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end && interrupt_signal() == 0)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  loop.stop();
  return loop.stats();
}

}  // namespace

std::shared_ptr<HapticsBenchOptions> add_haptics_bench_command(CLI::App& app) {
  auto opt = std::make_shared<HapticsBenchOptions>();
  CLI::App* cmd = app.add_subcommand(
      "haptics-bench", "Measure the 1 kHz haptic loop while the default scene runs in real time");
  cmd->add_option("--seconds", opt->seconds, "Wall-clock seconds to run")
      ->capture_default_str()
      ->check(finite_range(0.1, 3600));
  cmd->add_option("--script", opt->script_file,
                  "The path the emulated devices play, over and over (default: the built-in "
                  "examples/open_fascia.script)")
      ->check(non_empty());
  cmd->add_flag("--json", opt->json, "Print one JSON object on stdout");
  return opt;
}

int run_haptics_bench_command(const HapticsBenchOptions& o) {
  session::SurgicalSession s = session::make_surgical_session(scene::default_thorax_scene_params(),
                                                              session::SessionParams{});
  physics::Executor exec(1);  // physics on one core, haptics and the devices on the other
  LiveInputOptions lo;
  lo.devices = "emulator";
  lo.script_file = o.script_file;
  lo.port = 0;
  lo.loop_script = true;
  lo.program = "imasim haptics-bench";
  std::unique_ptr<LiveInputs> live;
  try {
    live = std::make_unique<LiveInputs>(lo);
  } catch (const std::exception& e) {
    std::cerr << "imasim haptics-bench: " << e.what() << '\n';
    return 2;
  }
  install_interrupt_handlers();
  // The floor before and after the loop, each a quarter of the run's length (0.25-2 s), so that
  // a machine that changes under the run shows in one of them.
  const double floor_part_s = std::clamp(o.seconds / 4, 0.25, 2.0);
  const haptics::HapticLoopStats floor_before = bare_sleeper(floor_part_s);
  const double dt = double(s.scene.patch.world.model.solver.dt);
  const auto steps = std::uint64_t(o.seconds / dt);
  runner::SessionRunner run(s, *live, exec, runner::Pacing::real_time);
  const std::uint64_t done = run.run(steps, [] { return interrupt_signal() != 0; }).steps;
  const nlohmann::ordered_json d = live->finish();
  const haptics::HapticLoopStats floor_after = bare_sleeper(floor_part_s);
  const nlohmann::ordered_json& loop = d["haptic_loop"];
  // The floor at its worse: the loop adds nothing measurable when it stays within 1.5 times it.
  const double floor_p99 =
      std::max(floor_before.period_p99_error_us, floor_after.period_p99_error_us);
  const std::uint64_t floor_missed = floor_before.missed_deadlines + floor_after.missed_deadlines;
  const double floor_s = double(floor_before.ticks + floor_after.ticks) / 1000.0;
  nlohmann::json j;
  for (const char* key : {"rate_hz", "period_p50_us", "period_p99_error_us", "period_max_us",
                          "missed_deadlines", "latency_p99_us"})
    j[key] = loop[key];
  j["force_max_n"] = d["force_max_n"];
  j["contacts"] = d["contacts"];
  j["floor_p99_error_us"] = floor_p99;
  j["floor_missed_deadlines"] = floor_missed;
  j["floor_seconds"] = floor_s;
  if (o.json) {
    // Exactly the keys of the JSON contract; the rest is in the text report.
    std::cout << j.dump() << '\n';
  } else {
    std::cout << "haptic loop: " << loop["ticks"] << " ticks, " << loop["rate_hz"]
              << " Hz, period p50 " << loop["period_p50_us"] << " us, p99 error "
              << loop["period_p99_error_us"] << " us, max " << loop["period_max_us"]
              << " us, missed deadlines " << loop["missed_deadlines"] << ", latency p99 "
              << loop["latency_p99_us"] << " us"
              << (loop["realtime_priority"].get<bool>() ? " (real-time priority)"
                                                        : " (normal priority)")
              << "; physics steps " << done << " of " << steps << "; largest force "
              << d["force_max_n"] << " N; safety " << d["safety"].dump() << '\n'
              << "the machine's floor (a bare 1 kHz sleeper, " << floor_s
              << " s before and after): p99 error " << floor_p99 << " us, missed deadlines "
              << floor_missed << '\n';
  }
  return interrupt_signal() != 0 ? interrupted_exit_status(interrupt_signal()) : 0;
}

}  // namespace imasim::cli
