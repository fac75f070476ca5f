// BM_SceneStep: one 5 ms step of the built-in thorax scene (tissues, beating or static heart as
// collider and boundary drive), on 1 or 2 threads, with the coarse objects swept 3 times (the
// default) or once.
#include <benchmark/benchmark.h>

#include <cstdint>

#include "physics/executor.hpp"
#include "scene/thorax_scene.hpp"

namespace {

void BM_SceneStep(benchmark::State& bench) {
  imasim::scene::ThoraxSceneParams params = imasim::scene::default_thorax_scene_params();
  params.playback.beating = bench.range(0) == 1;
  params.patch.solver.coarse_sweeps = static_cast<std::uint32_t>(bench.range(2));
  imasim::scene::ThoraxScene scene = imasim::scene::make_thorax_scene(params);
  imasim::physics::Executor exec(static_cast<int>(bench.range(1)));
  for (auto _ : bench) {
    if (!imasim::scene::step_thorax_scene(scene, exec).ok()) {
      bench.SkipWithError("step diverged");
      break;
    }
  }
}
BENCHMARK(BM_SceneStep)
    ->ArgNames({"beating", "threads", "coarse_sweeps"})
    ->ArgsProduct({{1, 0}, {1, 2}, {3}})
    ->Args({1, 1, 1})
    ->Args({1, 2, 1})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
