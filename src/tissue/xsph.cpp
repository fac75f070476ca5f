#include "tissue/xsph.hpp"

#include <algorithm>
#include <cmath>

namespace imasim::tissue {

namespace {

// W_ij = (1 - r / h)^2 for r < h, else 0; r = |x_j - x_i| is the same both ways, so W_ij = W_ji.
Real kernel(const Vec3& xi, const Vec3& xj, Real h) {
  const Real r = (xj - xi).norm();
  return r < h ? (1 - r / h) * (1 - r / h) : Real(0);
}

}  // namespace

void smooth_strand_velocities(TissueWorld& world) {
  physics::Particles& P = world.state.particles;
  std::vector<Vec3>& out = world.xsph_scratch;
  std::vector<Real>& S = world.xsph_weight;
  std::vector<Real>& W = world.xsph_kernel;  // W_ij per neighbour entry, computed once
  for (const StrandSet& set : world.strands) {
    if (set.xsph_coefficient <= 0) continue;
    const std::uint32_t count = set.particle_count();
    const Real h = set.xsph_radius, c = set.xsph_coefficient;
    auto live = [&](std::uint32_t k) { return set.diameter[k] != 0; };  // 0: removed by a cut
    // W_ij and S_i = sum_j W_ij over the live neighbours.
    for (std::uint32_t k = 0; k < count; ++k) {
      const std::uint32_t i = set.first_particle + k;
      S[i] = 0;
      for (std::uint32_t n = set.neighbour_start[k]; n < set.neighbour_start[k + 1]; ++n) {
        const bool both = live(k) && live(set.neighbours[n]);
        W[n] = both ? kernel(P.position[i], P.position[set.first_particle + set.neighbours[n]], h)
                    : Real(0);
        S[i] += W[n];
      }
    }
    // v_i' = v_i + c sum_j W_ij (v_j - v_i) / max(S_i, S_j): the pair's exchange is the same
    // both ways (neighbour lists are symmetric, equal masses within a set), so momentum is kept;
    // c sum_j W_ij / max(S_i, S_j) <= c <= 1, so v_i' is a convex combination of velocities.
    for (std::uint32_t k = 0; k < count; ++k) {
      const std::uint32_t i = set.first_particle + k;
      out[i] = P.velocity[i];
      if (!live(k)) continue;
      Vec3 pull = Vec3::Zero();
      for (std::uint32_t n = set.neighbour_start[k]; n < set.neighbour_start[k + 1]; ++n) {
        const Real w = W[n];
        if (w == 0) continue;
        const std::uint32_t j = set.first_particle + set.neighbours[n];
        pull += (w / std::max(S[i], S[j])) * (P.velocity[j] - P.velocity[i]);
      }
      out[i] += c * pull;
    }
    for (std::uint32_t k = 0; k < count; ++k) {
      P.velocity[set.first_particle + k] = out[set.first_particle + k];
    }
  }
}

}  // namespace imasim::tissue
