#include "tissue/xsph.hpp"

#include <algorithm>
#include <cmath>

namespace imasim::tissue {

namespace {

// W_ij = (1 - r / h)^2 for r < h, else 0; r = |x_j - x_i| is the same both ways, so W_ij = W_ji.
// Without a branch: pairs cross r = h at random as strands move, and a mispredicted branch
// would serialise the square roots.
Real kernel(const Vec3& xi, const Vec3& xj, Real h) {
  const Real q = std::max(Real(0), 1 - (xj - xi).norm() / h);
  return q * q;
}

}  // namespace

void smooth_strand_velocities(TissueWorld& world) {
  physics::Particles& P = world.state.particles;
  // Raw pointers, so the loops below keep their sums in registers (a store through one vector
  // could otherwise alias another's).
  const Vec3* x = P.position.data();
  Vec3* v = P.velocity.data();
  Vec3* out = world.xsph_scratch.data();
  Real* S = world.xsph_weight.data();
  Real* W = world.xsph_kernel.data();  // W_ij per neighbour entry, computed once per pair
  for (const StrandSet& set : world.strands) {
    if (set.xsph_coefficient <= 0) continue;
    const std::uint32_t count = set.particle_count(), first = set.first_particle;
    const Real h = set.xsph_radius, c = set.xsph_coefficient;
    const Real* diameter = set.diameter.data();  // 0: removed by a cut
    const std::uint32_t* start = set.neighbour_start.data();
    const std::uint32_t* neighbours = set.neighbours.data();
    // W_ij and S_i = sum_j W_ij over the live neighbours. Neighbour lists are symmetric and
    // sorted, so each pair is taken once, from its lower index (W_ij = W_ji): the entries above
    // k follow the ones below.
    for (std::uint32_t k = 0; k < count; ++k)
      S[first + k] = 0;
    for (std::uint32_t k = 0; k < count; ++k) {
      if (diameter[k] == 0) continue;
      const std::uint32_t i = first + k;
      const std::uint32_t* upper =
          std::upper_bound(neighbours + start[k], neighbours + start[k + 1], k);
      Real s_i = S[i];
      for (std::uint32_t n = std::uint32_t(upper - neighbours); n < start[k + 1]; ++n) {
        const std::uint32_t m = neighbours[n];
        const Real w = diameter[m] != 0 ? kernel(x[i], x[first + m], h) : Real(0);
        W[n] = w;
        s_i += w;
        S[first + m] += w;
      }
      S[i] = s_i;
    }
    // v_i' = v_i + c sum_j W_ij (v_j - v_i) / max(S_i, S_j): the pair's exchange is computed
    // once and given to i and taken from j (equal masses within a set), so momentum is kept
    // (to the rounding of the sums); c sum_j W_ij / max(S_i, S_j) <= c <= 1, so v_i' is a convex
    // combination of velocities.
    for (std::uint32_t k = 0; k < count; ++k)
      out[first + k] = v[first + k];
    for (std::uint32_t k = 0; k < count; ++k) {
      if (diameter[k] == 0) continue;
      const std::uint32_t i = first + k;
      const std::uint32_t* upper =
          std::upper_bound(neighbours + start[k], neighbours + start[k + 1], k);
      Vec3 gain = Vec3::Zero();
      for (std::uint32_t n = std::uint32_t(upper - neighbours); n < start[k + 1]; ++n) {
        const Real w = W[n];
        const std::uint32_t j = first + neighbours[n];
        // Selected, not branched on (see kernel); w > 0 implies S_i, S_j >= w > 0.
        const Real share = w > 0 ? c * w / std::max(S[i], S[j]) : Real(0);
        const Vec3 exchange = share * (v[j] - v[i]);
        gain += exchange;
        out[j] -= exchange;
      }
      out[i] += gain;
    }
    for (std::uint32_t k = 0; k < count; ++k)
      v[first + k] = out[first + k];
  }
}

}  // namespace imasim::tissue
