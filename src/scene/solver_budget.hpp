#pragma once
// What a step may cost, checked before a scene is built. The largest counts and solver
// settings each range allows, taken together, would make a step take minutes and a run look
// hung; these limits keep every accepted scene runnable. Measured on the reference machine
// (2 cores): the default thorax (about 8,000 particles, 32 sweeps) steps in about 3-4 ms, a
// particle sweep costing 14 ns there and 106 ns in the denser cloth (docs/PERFORMANCE.md).
#include <cstdint>
#include <string>

namespace imasim::scene {

struct ThoraxSceneParams;

// Solver sweeps per step (substeps x iterations): 16 times the default thorax's 32 and 100
// times the cloth's 5; the accuracy gained beyond is nil and a step would take seconds.
constexpr std::uint64_t kMaxSweepsPerStep = 512;
// Particles (and vertices updated each step) of a thorax scene: 12 times the default's. A
// patient mesh or a finer patch fits; a million does not step in real time by far.
constexpr std::uint64_t kMaxSceneParticles = 100'000;
// Particles x sweeps per step: about 0.2-0.6 s per step, 40-120 times slower than real time,
// where a run still reports within minutes.
constexpr std::uint64_t kMaxParticleSweepsPerStep = 8'000'000;

// Why a solver of `substeps` x `iterations` over `particles` is refused, or empty. `what`
// names the settings in the message ("solver.substeps x solver.iterations", "--substeps x
// --iterations").
std::string solver_budget_problem(std::uint64_t particles, std::uint64_t substeps,
                                  std::uint64_t iterations, const std::string& what);

// An upper bound on the particles a thorax scene gets (tissue meshes, the fascia's spare
// vertices, the most strands its densities can give, and the visual vessel's vertices), from
// its parameters alone: nothing is built.
std::uint64_t estimate_thorax_particles(const ThoraxSceneParams& params);

}  // namespace imasim::scene
