// BM_HarvestSecond: one simulated second (200 steps of 5 ms) of the scripted operator's harvest
// in the built-in scene, beating heart, one thread: the session continues from iteration to
// iteration through the plan's first seconds (approach, then the incision through the fascia).
// The counter `realtime_x` is simulated time over wall-clock time (the autopilot's target: >= 5).
// Argument implicit_fascia: 0 the default scene (the XPBD fascia), 1 with `fascia.solver =
// "implicit"` (the fascia at its strain-stiffening law, the instruments on it as bodies).
#include <benchmark/benchmark.h>

#include <string>

#include "autopilot/scripted_operator.hpp"
#include "console/console_mapping.hpp"
#include "physics/executor.hpp"

namespace {

void BM_HarvestSecond(benchmark::State& bench) {
  using namespace imasim;
  scene::ThoraxSceneParams scene_params = scene::default_thorax_scene_params();
  if (bench.range(0) == 1) scene_params.fascia_solver = std::string(scene::kImplicitFasciaSolver);
  session::SurgicalSession s =
      session::make_surgical_session(scene_params, session::SessionParams{});
  const autopilot::OperatorParams params;
  autopilot::ScriptedOperator op(autopilot::plan_harvest(s, params), params);
  physics::Executor exec(1);
  devices::ConsoleInput console;
  constexpr int kStepsPerSecond = 200;
  for (auto _ : bench) {
    for (int k = 0; k < kStepsPerSecond; ++k) {
      op.observe(devices::Hand::left, s.stations[0].pose);
      op.observe(devices::Hand::right, s.stations[1].pose);
      op.poll(s.scene.patch.world.state.time, console);
      if (!session::step_session(s, console::to_session_input(console, s), exec).ok()) {
        bench.SkipWithError("step diverged");
        return;
      }
    }
  }
  bench.counters["realtime_x"] =
      benchmark::Counter(double(bench.iterations()), benchmark::Counter::kIsRate);
}
BENCHMARK(BM_HarvestSecond)
    ->ArgName("implicit_fascia")
    ->Arg(0)
    ->Arg(1)
    ->Iterations(10)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

}  // namespace
