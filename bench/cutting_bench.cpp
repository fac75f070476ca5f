// Cutting costs (issue: instruments and cutting):
//   BM_FasciaCut: one step's cut on the default fascia, the electrode (8 mm) swept 1 mm or
//     10 mm across it through fresh tissue: the local remeshing and both topology changes.
//   BM_SessionStepWhileCutting: one 5 ms step of the surgical session while the example script
//     draws the cautery hook through the fascia in cut mode (t = 0.5 to 4.1 s), cycling over that
//     phase; "max_ms" is the slowest step seen (a cut must not stall a step past 5 ms).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>

#include "physics/executor.hpp"
#include "session/surgical_session.hpp"
#include "surgery/fascia_cut.hpp"
#include "tissue/thoracic_patch.hpp"

namespace {

using namespace imasim;

void BM_FasciaCut(benchmark::State& bench) {
  const tissue::ThoracicPatch fresh =
      tissue::make_thoracic_patch(tissue::default_thoracic_patch_params());
  const Real sweep = Real(bench.range(0)) * Real(1e-3);
  // Across the sheet at x = 0.5 mm, 30 mm from its end, the blade through it.
  const surgery::CuttingGeometry cut{Vec3(0.0005, -0.02, 0.03), Vec3(0, 0.02, 0),
                                     Vec3(0, 0, sweep)};
  const surgery::FasciaCutParams params;
  std::uint64_t edges = 0;
  for (auto _ : bench) {
    bench.PauseTiming();
    tissue::ThoracicPatch patch = fresh;
    surgery::FasciaCutter cutter = surgery::make_fascia_cutter(patch.fascia);
    bench.ResumeTiming();
    edges += surgery::cut_fascia(patch.world, params, cut, cutter).cut_edges;
  }
  bench.counters["cut_edges"] =
      benchmark::Counter(double(edges), benchmark::Counter::kAvgIterations);
}
BENCHMARK(BM_FasciaCut)
    ->ArgName("sweep_mm")
    ->Arg(1)
    ->Arg(4)
    ->Arg(10)
    ->Unit(benchmark::kMicrosecond);

void BM_SessionStepWhileCutting(benchmark::State& bench) {
  const surgery::InputScript script =
      surgery::load_input_script(IMASIM_SOURCE_DIR "/examples/open_fascia.script");
  physics::Executor exec(static_cast<int>(bench.range(0)));
  session::SurgicalSession start =
      session::make_surgical_session(scene::default_thorax_scene_params(), {});
  while (start.scene.patch.world.state.time < 0.5)
    session::step_session(start, session::sample_script(script, start.scene.patch.world.state.time),
                          exec);
  session::SurgicalSession s = start;
  double max_ms = 0;
  for (auto _ : bench) {
    const double t = s.scene.patch.world.state.time;
    if (t >= 4.1) {
      bench.PauseTiming();
      s = start;
      bench.ResumeTiming();
    }
    const auto t0 = std::chrono::steady_clock::now();
    if (!session::step_session(s, session::sample_script(script, s.scene.patch.world.state.time),
                               exec)
             .ok()) {
      bench.SkipWithError("step diverged");
      break;
    }
    max_ms = std::max(
        max_ms,
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  bench.counters["max_ms"] = max_ms;
}
BENCHMARK(BM_SessionStepWhileCutting)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
