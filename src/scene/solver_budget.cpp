#include "scene/solver_budget.hpp"

#include <cmath>

#include "scene/thorax_scene.hpp"

namespace imasim::scene {

std::string solver_budget_problem(std::uint64_t particles, std::uint64_t substeps,
                                  std::uint64_t iterations, const std::string& what) {
  const std::uint64_t sweeps = substeps * iterations;  // each at most 2^32: no overflow
  const std::string settings = what + " = " + std::to_string(substeps) + " x " +
                               std::to_string(iterations) + " = " + std::to_string(sweeps) +
                               " sweeps per step";
  if (sweeps > kMaxSweepsPerStep)
    return settings + ", above the limit of " + std::to_string(kMaxSweepsPerStep) +
           " (a step would take seconds; the default thorax uses 32)";
  if (particles > kMaxSceneParticles)
    return "the scene would have up to " + std::to_string(particles) +
           " particles, above the limit of " + std::to_string(kMaxSceneParticles) +
           " (a step would take seconds): use coarser counts";
  if (particles * sweeps > kMaxParticleSweepsPerStep)
    return settings + " over up to " + std::to_string(particles) +
           " particles: " + std::to_string(particles * sweeps) +
           " particle sweeps per step, above the limit of " +
           std::to_string(kMaxParticleSweepsPerStep) +
           " (a step would take about a second): use fewer sweeps or coarser counts";
  return {};
}

std::uint64_t estimate_thorax_particles(const ThoraxSceneParams& params) {
  const tissue::ThoracicPatchParams& p = params.patch;
  using U = std::uint64_t;
  const U wall = U(p.wall.nu) * p.wall.nv;
  const U fascia = U(p.fascia.nx) * p.fascia.ny + p.fascia.object.spare_vertices;
  const U vessel = U(p.vessel.coarse_rings) * p.vessel.coarse_segments;
  const U fine_vessel = U(p.vessel.fine_rings) * p.vessel.fine_segments;
  // At most ceil(sigma) strands per face of the surface they start on, n + 1 particles each.
  const auto strands = [](const tissue::StrandSetParams& s, U faces) {
    const double per_face = std::ceil(double(s.generation.strands_per_face));
    return U(per_face) * faces * (U(s.generation.segments) + 1);
  };
  const U vessel_faces = 2 * U(p.vessel.coarse_rings) * p.vessel.coarse_segments;
  const U fascia_faces = 2 * U(p.fascia.nx - 1) * (p.fascia.ny - 1);
  return wall + fascia + vessel + fine_vessel + strands(p.ima_fat, vessel_faces) +
         strands(p.fascia_fat, fascia_faces);
}

}  // namespace imasim::scene
