#include "tissue/coupling.hpp"

#include <limits>

#include "geometry/uniform_grid.hpp"

namespace imasim::tissue {

void apply_coupling(const OffsetCoupling& c, physics::Particles& P, const std::vector<Vec3>& ref,
                    std::span<const Vec3> start, Real dt, const CouplingFlags& flags,
                    PairsApplied which) {
  const bool velocities = !start.empty() && dt > 0;
  const Real inverse_dt = velocities ? 1 / dt : Real(0);
  for (const auto& [j, i] : c.pairs) {
    if (destination_left(c, i, flags) || P.is_fixed(i)) continue;
    const bool follows = pair_follows(c, j, flags);
    if (which == PairsApplied::following && !follows) continue;
    if (which == PairsApplied::relaxing && (follows || c.decay == 1)) continue;
    const Vec3 target = follows ? follow_target(c, P.position[j], ref[j], ref[i])
                                : relaxed_target(c, P.position[i], ref[i]);
    if (velocities) P.velocity[i] = inverse_dt * (target - start[i]);
    P.position[i] = target;
  }
}

void append_follow_rows(const OffsetCoupling& c, const physics::Particles& P,
                        const std::vector<Vec3>& ref, const CouplingFlags& flags,
                        std::vector<physics::FollowRow>& out) {
  if (c.beta == Beta::zero) return;
  for (const auto& [j, i] : c.pairs) {
    if (!pair_follows(c, j, flags) || destination_left(c, i, flags) || P.is_fixed(i)) continue;
    out.push_back({j, i, ref[j], ref[i], c.lambda_max});
  }
}

std::vector<std::pair<std::uint32_t, std::uint32_t>> nearest_source_pairs(
    const physics::Particles& P, const std::vector<std::uint32_t>& sources,
    const std::vector<std::uint32_t>& destinations, Real radius) {
  std::vector<geometry::Box> boxes;
  boxes.reserve(sources.size());
  for (std::uint32_t s : sources)
    boxes.emplace_back(P.rest_position[s]);
  const geometry::UniformGrid grid(boxes, radius);
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;
  std::vector<std::uint32_t> visited;
  std::uint32_t stamp = 0;
  for (std::uint32_t d : destinations) {
    const Vec3& x = P.rest_position[d];
    Real best = radius * radius;
    std::uint32_t best_source = std::numeric_limits<std::uint32_t>::max();
    grid.visit(geometry::Box(x - Vec3::Constant(radius), x + Vec3::Constant(radius)), visited,
               stamp, [&](std::uint32_t k) {
                 const Real d2 = (P.rest_position[sources[k]] - x).squaredNorm();
                 if (d2 < best || (d2 == best && sources[k] < best_source)) {
                   best = d2;
                   best_source = sources[k];
                 }
               });
    if (best_source != std::numeric_limits<std::uint32_t>::max())
      pairs.emplace_back(best_source, d);
  }
  return pairs;
}

}  // namespace imasim::tissue
