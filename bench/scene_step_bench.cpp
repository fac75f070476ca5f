// BM_SceneStep: one 5 ms step of the built-in thorax scene (tissues, beating or static heart as
// collider and boundary drive), on 1 or 2 threads, with the coarse objects swept 3 times (the
// default) or once.
// BM_SceneStepImplicitFascia: the same (beating, one thread) with the fascia solved by the
// implicit membrane step (scene/implicit_mesh_scene.hpp): at the toe's modulus throughout
// (law:0, the XPBD rows' material) or with the fascia's law (law:1, 2.65 MPa past 5 % strain).
// Counters: Newton iterations and refactorisations of the fascia's last step.
// BM_ImplicitFasciaRefit: what a cut of the implicit fascia costs on top of the cut itself, the
// implicit step rebuilt from the mesh (refit_scene_fascia: springs, hinges, the pattern analysed).
#include <benchmark/benchmark.h>

#include <cstdint>

#include "physics/executor.hpp"
#include "scene/thorax_scene.hpp"
#include "tissue/mesh_object.hpp"

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

void BM_SceneStepImplicitFascia(benchmark::State& bench) {
  imasim::scene::ThoraxScene scene =
      imasim::scene::make_thorax_scene(imasim::scene::default_thorax_scene_params());
  const imasim::physics::MembraneMaterial m = imasim::tissue::default_fascia_membrane();
  const imasim::Real linear = bench.range(0) == 1 ? imasim::Real(2.65e6) : m.youngs_modulus;
  imasim::scene::use_implicit_fascia(
      scene, {m.youngs_modulus, linear, imasim::Real(0.05), m.thickness, imasim::Real(1100)});
  imasim::physics::Executor exec(1);
  for (int k = 0; k < 40; ++k)  // past the first steps' settling
    imasim::scene::step_thorax_scene(scene, exec);
  double iterations = 0, factorizations = 0, steps = 0;
  for (auto _ : bench) {
    if (!imasim::scene::step_thorax_scene(scene, exec).ok()) {
      bench.SkipWithError("step diverged");
      break;
    }
    iterations += scene.implicit_fascia->last.iterations;
    factorizations += scene.implicit_fascia->last.factorizations;
    ++steps;
  }
  bench.counters["newton_per_step"] = steps > 0 ? iterations / steps : 0;
  bench.counters["factorizations_per_step"] = steps > 0 ? factorizations / steps : 0;
}
BENCHMARK(BM_SceneStepImplicitFascia)
    ->ArgName("law")
    ->Arg(0)
    ->Arg(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

void BM_ImplicitFasciaRefit(benchmark::State& bench) {
  imasim::scene::ThoraxScene scene =
      imasim::scene::make_thorax_scene(imasim::scene::default_thorax_scene_params());
  const imasim::physics::MembraneMaterial m = imasim::tissue::default_fascia_membrane();
  imasim::scene::use_implicit_fascia(scene, {m.youngs_modulus, imasim::Real(2.65e6),
                                             imasim::Real(0.05), m.thickness, imasim::Real(1100)});
  for (auto _ : bench)
    imasim::scene::refit_scene_fascia(scene);
}
BENCHMARK(BM_ImplicitFasciaRefit)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
