// BM_ImplicitMembraneStep: one 5 ms backward-Euler step of a fascia-sized membrane (n x n
// vertices over 50 mm, perimeter fixed, toe 0.1 MPa, linear 2.65 MPa past 5 % strain, 1 mm) held
// by a point force at its centre that varies as a tool's would (0.3 N +- 0.05 N at 2 Hz), after
// 0.3 s of loading, its hinges bending as the fascia's; Newton to 1e-6 N
// (physics/implicit_membrane.hpp). Counters: Newton iterations, refactorisations a step, free
// vertices.
#include <benchmark/benchmark.h>

#include <cmath>

#include "geometry/grid_rectangle.hpp"
#include "physics/membrane_springs.hpp"

namespace {

using imasim::Real;
using imasim::Vec3;

void BM_ImplicitMembraneStep(benchmark::State& bench) {
  using namespace imasim::physics;
  const auto n = static_cast<std::uint32_t>(bench.range(0));
  const imasim::geometry::TriangleMesh mesh =
      imasim::geometry::make_grid_rectangle({0.05, 0.05, n, n});
  StiffeningMembrane fascia{0.1e6, 2.65e6, 0.05, 1e-3, 1100};
  std::vector<std::uint8_t> fixed(mesh.vertices.size(), 0);
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i)
      fixed[imasim::geometry::grid_index(i, j, n)] = i == 0 || j == 0 || i + 1 == n || j + 1 == n;
  const Real h = 0.005;
  // The plate's D of the toe-region fascia, E t^3 / (12 (1 - nu^2)) with nu = 0.45 (unit: N m).
  const Real bending = 0.1e6 * 1e-9 / (12 * (1 - 0.45 * 0.45));
  ImplicitMembrane membrane(membrane_masses(mesh, fascia), fixed, membrane_springs(mesh, fascia), h,
                            membrane_hinges(mesh, bending));
  std::vector<Vec3> x = mesh.vertices, v(x.size(), Vec3::Zero()), force(x.size(), Vec3::Zero());
  const std::uint32_t centre = imasim::geometry::grid_index(n / 2, n / 2, n);
  const Vec3 gravity(0, -9.81, 0);
  const ImplicitSolveParams solve;
  int k = 0;
  auto load = [&] {
    const double t = k * h;
    force[centre] = Vec3(0, -std::min(1.0, t / 0.2) * (0.3 + 0.05 * std::sin(2 * M_PI * 2 * t)), 0);
    ++k;
  };
  for (int warm = 0; warm < 60; ++warm) {
    load();
    membrane.step(x, v, {gravity, force, {}}, solve);
  }
  std::uint64_t iterations = 0, factorizations = 0, steps = 0;
  for (auto _ : bench) {
    load();
    const ImplicitStepReport r = membrane.step(x, v, {gravity, force, {}}, solve);
    if (!r.ok) {
      bench.SkipWithError("factorisation failed");
      break;
    }
    iterations += r.iterations;
    factorizations += r.factorizations;
    ++steps;
  }
  bench.counters["newton_per_step"] = steps ? double(iterations) / double(steps) : 0;
  bench.counters["factorizations_per_step"] = steps ? double(factorizations) / double(steps) : 0;
  bench.counters["free_vertices"] = double(membrane.free_count());
}
BENCHMARK(BM_ImplicitMembraneStep)
    ->ArgName("n")
    ->Arg(17)
    ->Arg(24)
    ->Arg(33)
    ->Unit(benchmark::kMillisecond);

}  // namespace
