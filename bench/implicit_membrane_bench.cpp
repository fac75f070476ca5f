// The implicit membrane step (physics/implicit_membrane.hpp) on a fascia-sized square: n x n
// vertices over 50 mm, perimeter fixed, toe 0.1 MPa, linear 2.65 MPa past 5 % strain, 1 mm thick,
// its hinges bending as the fascia's, under gravity; Newton to 1e-6 N. Counters: Newton
// iterations and refactorisations a step.
//   BM_ImplicitMembraneStep: held by a point force at its centre that varies as a tool's would
//     (0.3 N +- 0.05 N at 2 Hz), after 0.3 s of loading; also the free vertices.
//   BM_ImplicitMembraneProxyPress (n = 24): pressed by a 5 mm ball that is a body solved with
//     it, held to its device by the tool proxy's coupling (1000 N/m, 5 N s/m), the device 4 +-
//     0.5 mm at 2 Hz past the rest surface, the contacts gathered each step around the ball.
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>

#include "geometry/grid_rectangle.hpp"
#include "physics/membrane_springs.hpp"

namespace {

using imasim::Real;
using imasim::Vec3;
using namespace imasim::physics;

constexpr Real kStep = 0.005;  // (unit: s)
const Vec3 kGravity(0, -9.81, 0);

struct Square {
  imasim::geometry::TriangleMesh mesh;
  std::vector<std::uint8_t> fixed;
  std::unique_ptr<ImplicitMembrane> membrane;
  std::vector<Vec3> x, v;
};

Square make_square(std::uint32_t n, std::uint32_t bodies) {
  Square s;
  s.mesh = imasim::geometry::make_grid_rectangle({0.05, 0.05, n, n});
  const StiffeningMembrane fascia{0.1e6, 2.65e6, 0.05, 1e-3, 1100};
  s.fixed.assign(s.mesh.vertices.size(), 0);
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i)
      s.fixed[imasim::geometry::grid_index(i, j, n)] = i == 0 || j == 0 || i + 1 == n || j + 1 == n;
  // The plate's D of the toe-region fascia, E t^3 / (12 (1 - nu^2)) with nu = 0.45 (unit: N m).
  const Real bending = 0.1e6 * 1e-9 / (12 * (1 - 0.45 * 0.45));
  s.membrane = std::make_unique<ImplicitMembrane>(membrane_masses(s.mesh, fascia), s.fixed,
                                                  membrane_springs(s.mesh, fascia), kStep,
                                                  membrane_hinges(s.mesh, bending), bodies);
  s.x = s.mesh.vertices;
  s.v.assign(s.x.size(), Vec3::Zero());
  return s;
}

// Warms up, then times `step` (returning an ImplicitStepReport) and sets the counters.
template <class Step>
void run(benchmark::State& bench, int warm_up_steps, Step step) {
  for (int k = 0; k < warm_up_steps; ++k)
    step();
  std::uint64_t iterations = 0, factorizations = 0, steps = 0;
  for (auto _ : bench) {
    const ImplicitStepReport r = step();
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
}

void BM_ImplicitMembraneStep(benchmark::State& bench) {
  const auto n = static_cast<std::uint32_t>(bench.range(0));
  Square s = make_square(n, 0);
  std::vector<Vec3> force(s.x.size(), Vec3::Zero());
  const std::uint32_t centre = imasim::geometry::grid_index(n / 2, n / 2, n);
  const ImplicitSolveParams solve;
  int k = 0;
  run(bench, 60, [&] {
    const double t = k++ * kStep;
    force[centre] = Vec3(0, -std::min(1.0, t / 0.2) * (0.3 + 0.05 * std::sin(2 * M_PI * 2 * t)), 0);
    return s.membrane->step(s.x, s.v, {kGravity, force, {}, {}}, solve);
  });
  bench.counters["free_vertices"] = double(s.membrane->free_count());
}
BENCHMARK(BM_ImplicitMembraneStep)
    ->ArgName("n")
    ->Arg(17)
    ->Arg(24)
    ->Arg(33)
    ->Unit(benchmark::kMillisecond);

void BM_ImplicitMembraneProxyPress(benchmark::State& bench) {
  constexpr std::uint32_t n = 24;
  constexpr Real radius = 0.005;
  Square s = make_square(n, 1);
  const Vec3 centre = s.mesh.vertices[imasim::geometry::grid_index(n / 2, n / 2, n)];
  std::vector<MembraneBody> body = {{centre, 1000, 5, centre + Vec3(0, radius + 0.01, 0)}};
  std::vector<MembraneContact> contacts;
  contacts.reserve(s.x.size());
  const ImplicitSolveParams solve;
  int k = 0;
  run(bench, 80, [&] {
    const double t = k++ * kStep;
    const double depth = std::min(1.0, t / 0.3) * (0.004 + 0.0005 * std::sin(2 * M_PI * 2 * t));
    body[0].anchor = centre + Vec3(0, radius - depth, 0);
    contacts.clear();
    for (std::uint32_t u = 0; u < s.x.size(); ++u) {
      const Vec3 out = s.x[u] - body[0].position;
      if (s.fixed[u] || !(out.norm() > 0) || out.norm() > radius + 0.003) continue;
      contacts.push_back({u, body[0].position + radius * out.normalized(), out.normalized(), 0});
    }
    return s.membrane->step(s.x, s.v, {kGravity, {}, contacts, body}, solve);
  });
}
BENCHMARK(BM_ImplicitMembraneProxyPress)->Unit(benchmark::kMillisecond);

}  // namespace
