#include "tissue/xsph.hpp"

#include <algorithm>
#include <cmath>

#include "physics/simd.hpp"

namespace imasim::tissue {

namespace {

using VS = physics::simd::V<Real>;
constexpr std::uint32_t kLanes = physics::simd::kLanes<Real>;

// W_ij = (1 - r / h)^2 for r < h, else 0; r = |x_j - x_i| is the same both ways, so W_ij = W_ji.
// Without a branch: pairs cross r = h at random as strands move, and a mispredicted branch
// would serialise the square roots.
Real kernel(const Vec3& xi, const Vec3& xj, Real h) {
  const Real q = std::max(Real(0), 1 - (xj - xi).norm() / h);
  return q * q;
}

// W of every pair of the set (0 where either particle was removed by a cut), kLanes pairs at a
// time: the square roots and divisions of a batch go through the vector units together. The
// formulas of kernel(), lane by lane (the last bit may differ where the compiler fuses a multiply
// and an add differently; each pair always takes the same path, so runs stay repeatable).
void pair_kernels(const StrandSet& set, const Vec3* x, Real* W) {
  const auto pairs = static_cast<std::uint32_t>(set.pair_lower.size());
  const std::uint32_t first = set.first_particle;
  const std::uint32_t* lower = set.pair_lower.data();
  const std::uint32_t* upper = set.pair_upper.data();
  const Real* diameter = set.diameter.data();  // 0: removed by a cut
  const Real h = set.xsph_radius;
  std::uint32_t p = 0;
  for (; p + kLanes <= pairs; p += kLanes) {
    alignas(physics::simd::kBytes) Real dx[kLanes], dy[kLanes], dz[kLanes], live[kLanes];
    for (std::uint32_t k = 0; k < kLanes; ++k) {
      const Vec3 d = x[first + upper[p + k]] - x[first + lower[p + k]];
      dx[k] = d.x(), dy[k] = d.y(), dz[k] = d.z();
      live[k] = diameter[lower[p + k]] != 0 && diameter[upper[p + k]] != 0 ? 1 : 0;
    }
    const VS vx = physics::simd::load(dx), vy = physics::simd::load(dy),
             vz = physics::simd::load(dz);
    const VS r = physics::simd::sqrt<Real>(vx * vx + vy * vy + vz * vz);
    VS q = 1 - r / h;
    q = q > 0 ? q : VS{} + 0;  // std::max(0, q)
    const VS w = physics::simd::load(live) != 0 ? q * q : VS{} + 0;
    for (std::uint32_t k = 0; k < kLanes; ++k)
      W[p + k] = w[k];
  }
  for (; p < pairs; ++p) {
    const bool live = diameter[lower[p]] != 0 && diameter[upper[p]] != 0;
    W[p] = live ? kernel(x[first + lower[p]], x[first + upper[p]], h) : Real(0);
  }
}

// Each pair's exchange weight c W_ij / max(S_i, S_j) (0 where W_ij = 0), kLanes at a time.
void pair_shares(const StrandSet& set, const Real* W, const Real* S, Real* share) {
  const auto pairs = static_cast<std::uint32_t>(set.pair_lower.size());
  const std::uint32_t first = set.first_particle;
  const std::uint32_t* lower = set.pair_lower.data();
  const std::uint32_t* upper = set.pair_upper.data();
  const Real c = set.xsph_coefficient;
  std::uint32_t p = 0;
  for (; p + kLanes <= pairs; p += kLanes) {
    alignas(physics::simd::kBytes) Real si[kLanes], sj[kLanes];
    for (std::uint32_t k = 0; k < kLanes; ++k) {
      si[k] = S[first + lower[p + k]];
      sj[k] = S[first + upper[p + k]];
    }
    const VS w = physics::simd::load(W + p), a = physics::simd::load(si),
             b = physics::simd::load(sj);
    const auto positive = w > 0;
    const VS larger = a < b ? b : a;  // std::max(a, b)
    const VS s = c * w / (positive ? larger : VS{} + 1);
    const VS out = positive ? s : VS{} + 0;
    for (std::uint32_t k = 0; k < kLanes; ++k)
      share[p + k] = out[k];
  }
  for (; p < pairs; ++p) {
    const Real w = W[p];
    share[p] = w > 0 ? c * w / std::max(S[first + lower[p]], S[first + upper[p]]) : Real(0);
  }
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
  Real* W = world.xsph_kernel.data();  // W_ij per pair, computed once per pair
  Real* share = world.xsph_share.data();
  for (const StrandSet& set : world.strands) {
    if (set.xsph_coefficient <= 0) continue;
    const std::uint32_t count = set.particle_count(), first = set.first_particle;
    const Real* diameter = set.diameter.data();  // 0: removed by a cut
    const std::uint32_t* pair_start = set.pair_start.data();
    const std::uint32_t* upper = set.pair_upper.data();
    pair_kernels(set, x, W);
    // S_i = sum_j W_ij over the live neighbours. Each pair is taken once, from its lower index
    // (W_ij = W_ji), in a fixed order: the sums do not depend on how W was computed.
    for (std::uint32_t k = 0; k < count; ++k)
      S[first + k] = 0;
    for (std::uint32_t k = 0; k < count; ++k) {
      if (diameter[k] == 0) continue;
      const std::uint32_t i = first + k;
      Real s_i = S[i];
      for (std::uint32_t p = pair_start[k]; p < pair_start[k + 1]; ++p) {
        const Real w = W[p];
        s_i += w;
        S[first + upper[p]] += w;
      }
      S[i] = s_i;
    }
    // v_i' = v_i + c sum_j W_ij (v_j - v_i) / max(S_i, S_j): the pair's exchange is computed
    // once and given to i and taken from j (equal masses within a set), so momentum is kept
    // (to the rounding of the sums); c sum_j W_ij / max(S_i, S_j) <= c <= 1, so v_i' is a convex
    // combination of velocities.
    pair_shares(set, W, S, share);
    for (std::uint32_t k = 0; k < count; ++k)
      out[first + k] = v[first + k];
    for (std::uint32_t k = 0; k < count; ++k) {
      if (diameter[k] == 0) continue;
      const std::uint32_t i = first + k;
      Vec3 gain = Vec3::Zero();
      for (std::uint32_t p = pair_start[k]; p < pair_start[k + 1]; ++p) {
        const std::uint32_t j = first + upper[p];
        const Vec3 exchange = share[p] * (v[j] - v[i]);
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
