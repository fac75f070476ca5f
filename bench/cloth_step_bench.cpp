// BM_ClothStep: one 5 ms step of the cloth verification scene (PBD, distance + dihedral,
// 5 iterations, 1 substep), N x N vertices, on 1 or 2 threads. Run with `make bench`.
#include <benchmark/benchmark.h>

#include "physics/executor.hpp"
#include "physics/step.hpp"
#include "scene/cloth_scene.hpp"

namespace {

void BM_ClothStep(benchmark::State& bench) {
  imasim::scene::ClothParams params;
  params.n = static_cast<std::uint32_t>(bench.range(0));
  imasim::scene::ClothScene scene = imasim::scene::make_cloth_scene(params);
  imasim::physics::Executor exec(static_cast<int>(bench.range(1)));
  for (auto _ : bench) {
    const auto result = imasim::physics::step(scene.model, scene.state, exec);
    if (!result.ok()) {
      bench.SkipWithError("step diverged");
      break;
    }
  }
  bench.counters["particles"] = static_cast<double>(scene.state.particles.size());
  bench.counters["constraints"] = static_cast<double>(scene.state.constraints.distance.size() +
                                                      scene.state.constraints.dihedral.size());
}

BENCHMARK(BM_ClothStep)
    ->ArgNames({"n", "threads"})
    ->ArgsProduct({{32, 64, 128, 256}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace
