// BM_TissueStep: one 5 ms step of the default thoracic-wall patch (fascia, IMA coarse + fine,
// IMA and fascia fat strands, chest wall, couplings), on 1 or 2 threads.
// BM_StrandGeneration: generating the fascia-to-wall strands of that patch.
// BM_StrandTearCheck: the session's per-step check of that patch's strands for tearing, none torn.
// BM_StrandSmoothing: the XSPH smoothing of that patch's strands (once a step), on 1 or 2
// threads.
#include <benchmark/benchmark.h>

#include "physics/executor.hpp"
#include "tissue/strand_tear.hpp"
#include "tissue/thoracic_patch.hpp"
#include "tissue/tissue_step.hpp"
#include "tissue/xsph.hpp"

namespace {

using namespace imasim;

void BM_TissueStep(benchmark::State& bench) {
  tissue::ThoracicPatch patch =
      tissue::make_thoracic_patch(tissue::default_thoracic_patch_params());
  physics::Executor exec(static_cast<int>(bench.range(0)));
  for (auto _ : bench) {
    if (!tissue::step_tissue(patch.world, exec).ok()) {
      bench.SkipWithError("step diverged");
      break;
    }
  }
  bench.counters["particles"] = static_cast<double>(patch.world.state.particles.size());
}
BENCHMARK(BM_TissueStep)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_StrandTearCheck(benchmark::State& bench) {
  tissue::ThoracicPatch patch =
      tissue::make_thoracic_patch(tissue::default_thoracic_patch_params());
  std::vector<tissue::StrandTear> torn;
  std::uint32_t strands = 0;
  for (const tissue::StrandSet& set : patch.world.strands)
    strands += set.strand_count;
  for (auto _ : bench)
    benchmark::DoNotOptimize(tissue::tear_overstretched_strands(patch.world, torn));
  if (!torn.empty()) bench.SkipWithError("a strand tore at rest");
  bench.counters["strands"] = strands;
}
BENCHMARK(BM_StrandTearCheck)->Unit(benchmark::kMicrosecond);

void BM_StrandGeneration(benchmark::State& bench) {
  const tissue::ThoracicPatchParams params = tissue::default_thoracic_patch_params();
  tissue::ThoracicPatch patch = tissue::make_thoracic_patch(params);
  const tissue::TissueWorld& w = patch.world;
  auto mesh_of = [&](std::uint32_t index) {
    const tissue::MeshObject& m = w.meshes[index];
    geometry::TriangleMesh mesh;
    const auto x = tissue::mesh_positions(w, m);
    mesh.vertices.assign(x.begin(), x.end());
    mesh.triangles = m.triangles;
    return mesh;
  };
  const geometry::TriangleMesh fascia = mesh_of(patch.fascia), wall = mesh_of(patch.wall);
  std::size_t strands = 0;
  for (auto _ : bench) {
    strands = tissue::generate_strands(fascia, wall, params.fascia_fat.generation).strands.size();
    benchmark::DoNotOptimize(strands);
  }
  bench.counters["strands"] = static_cast<double>(strands);
}
BENCHMARK(BM_StrandGeneration)->Unit(benchmark::kMillisecond);

void BM_StrandSmoothing(benchmark::State& bench) {
  tissue::ThoracicPatch patch =
      tissue::make_thoracic_patch(tissue::default_thoracic_patch_params());
  physics::Executor exec(static_cast<int>(bench.range(0)));
  for (int n = 0; n < 20; ++n)  // the strands moving, as they are when smoothed
    if (!tissue::step_tissue(patch.world, exec).ok()) bench.SkipWithError("step diverged");
  std::size_t pairs = 0;
  for (const tissue::StrandSet& set : patch.world.strands)
    pairs += set.pair_lower.size();
  for (auto _ : bench)
    tissue::smooth_strand_velocities(patch.world, exec);
  bench.counters["pairs"] = static_cast<double>(pairs);
}
BENCHMARK(BM_StrandSmoothing)
    ->ArgName("threads")
    ->Arg(1)
    ->Arg(2)
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime();

}  // namespace
