#include "tissue/xsph.hpp"

#include <algorithm>
#include <cmath>

#include "physics/simd.hpp"

namespace imasim::tissue {

namespace {

using VS = physics::simd::V<Real>;
constexpr std::uint32_t kLanes = physics::simd::kLanes<Real>;

// A batch whose lane k is f(k), built in registers (physics/simd.hpp).
template <class F>
VS lanes(const F& f) {
  return physics::simd::lanes<Real>(
      [&](std::size_t k) { return f(static_cast<std::uint32_t>(k)); });
}

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
void pair_kernels(const StrandSet& set, const Vec3* x, Real* W, std::uint32_t begin,
                  std::uint32_t end) {
  const std::uint32_t first = set.first_particle;
  const std::uint32_t* lower = set.pair_lower.data();
  const std::uint32_t* upper = set.pair_upper.data();
  const Real* diameter = set.diameter.data();  // 0: removed by a cut
  const Real h = set.xsph_radius;
  std::uint32_t p = begin;
  for (; p + kLanes <= end; p += kLanes) {
    const VS vx = lanes(
        [&](std::uint32_t k) { return x[first + upper[p + k]].x() - x[first + lower[p + k]].x(); });
    const VS vy = lanes(
        [&](std::uint32_t k) { return x[first + upper[p + k]].y() - x[first + lower[p + k]].y(); });
    const VS vz = lanes(
        [&](std::uint32_t k) { return x[first + upper[p + k]].z() - x[first + lower[p + k]].z(); });
    const VS live = lanes([&](std::uint32_t k) {
      return diameter[lower[p + k]] != 0 && diameter[upper[p + k]] != 0 ? Real(1) : Real(0);
    });
    const VS r = physics::simd::sqrt<Real>(vx * vx + vy * vy + vz * vz);
    VS q = 1 - r / h;
    q = q > 0 ? q : VS{} + 0;  // std::max(0, q)
    const VS w = live != 0 ? q * q : VS{} + 0;
    for (std::uint32_t k = 0; k < kLanes; ++k)
      W[p + k] = w[k];
  }
  for (; p < end; ++p) {
    const bool live = diameter[lower[p]] != 0 && diameter[upper[p]] != 0;
    W[p] = live ? kernel(x[first + lower[p]], x[first + upper[p]], h) : Real(0);
  }
}

// Each pair's exchange weight c W_ij / max(S_i, S_j) (0 where W_ij = 0), kLanes at a time.
void pair_shares(const StrandSet& set, const Real* W, const Real* S, Real* share,
                 std::uint32_t begin, std::uint32_t end) {
  const std::uint32_t first = set.first_particle;
  const std::uint32_t* lower = set.pair_lower.data();
  const std::uint32_t* upper = set.pair_upper.data();
  const Real c = set.xsph_coefficient;
  std::uint32_t p = begin;
  for (; p + kLanes <= end; p += kLanes) {
    const VS w = physics::simd::load(W + p);
    const VS a = lanes([&](std::uint32_t k) { return S[first + lower[p + k]]; });
    const VS b = lanes([&](std::uint32_t k) { return S[first + upper[p + k]]; });
    const auto positive = w > 0;
    const VS larger = a < b ? b : a;  // std::max(a, b)
    const VS s = c * w / (positive ? larger : VS{} + 1);
    const VS out = positive ? s : VS{} + 0;
    for (std::uint32_t k = 0; k < kLanes; ++k)
      share[p + k] = out[k];
  }
  for (; p < end; ++p) {
    const Real w = W[p];
    share[p] = w > 0 ? c * w / std::max(S[first + lower[p]], S[first + upper[p]]) : Real(0);
  }
}

// Chunks of the parallel passes: over pairs a multiple of the SIMD width, so that only the last
// pairs take the scalar tail, as in one pass over them all (the same bits on any thread count).
constexpr std::size_t kPairChunk = 2048, kParticleChunk = 512;
static_assert(kPairChunk % kLanes == 0);

void smooth_set(TissueWorld& world, const StrandSet& set, const physics::Executor& exec) {
  physics::Particles& P = world.state.particles;
  // Raw pointers, so the loops below keep their sums in registers (a store through one vector
  // could otherwise alias another's).
  const Vec3* x = P.position.data();
  Vec3* v = P.velocity.data();
  Vec3* out = world.xsph_scratch.data();
  Real* S = world.xsph_weight.data();
  Real* W = world.xsph_kernel.data();  // W_ij per pair, computed once per pair
  Real* share = world.xsph_share.data();
  const std::uint32_t count = set.particle_count(), first = set.first_particle;
  const auto pairs = static_cast<std::uint32_t>(set.pair_lower.size());
  const Real* diameter = set.diameter.data();  // 0: removed by a cut
  const std::uint32_t* pair_start = set.pair_start.data();
  const std::uint32_t* lower = set.pair_lower.data();
  const std::uint32_t* upper = set.pair_upper.data();
  const std::uint32_t* incoming_start = set.incoming_start.data();
  const std::uint32_t* incoming = set.incoming_pair.data();
  auto u32 = [](std::size_t n) { return static_cast<std::uint32_t>(n); };
  exec.for_chunks(pairs, kPairChunk,
                  [&](std::size_t b, std::size_t e) { pair_kernels(set, x, W, u32(b), u32(e)); });
  // S_i = sum_j W_ij over the live neighbours, in a fixed order: the pairs (j, i) by ascending
  // j, then (i, j) by ascending j, each particle gathering its own (the order one pass scattering
  // every pair from its lower particle would add them in).
  exec.for_chunks(count, kParticleChunk, [&](std::size_t b, std::size_t e) {
    for (std::uint32_t k = u32(b); k < e; ++k) {
      Real s_k = 0;
      for (std::uint32_t q = incoming_start[k]; q < incoming_start[k + 1]; ++q) {
        const std::uint32_t p = incoming[q];
        if (diameter[lower[p]] != 0) s_k += W[p];
      }
      if (diameter[k] != 0) {
        for (std::uint32_t p = pair_start[k]; p < pair_start[k + 1]; ++p)
          s_k += W[p];
      }
      S[first + k] = s_k;
    }
  });
  exec.for_chunks(pairs, kPairChunk, [&](std::size_t b, std::size_t e) {
    pair_shares(set, W, S, share, u32(b), u32(e));
  });
  // v_i' = v_i + c sum_j W_ij (v_j - v_i) / max(S_i, S_j): each pair's exchange, the same
  // product for both particles, is taken from the upper one and given to the lower, so momentum
  // is kept (to the rounding of the sums); c sum_j W_ij / max(S_i, S_j) <= c <= 1, so v_i' is a
  // convex combination of velocities. Gathered per particle in the order above.
  exec.for_chunks(count, kParticleChunk, [&](std::size_t b, std::size_t e) {
    for (std::uint32_t k = u32(b); k < e; ++k) {
      const std::uint32_t i = first + k;
      Vec3 o = v[i];
      for (std::uint32_t q = incoming_start[k]; q < incoming_start[k + 1]; ++q) {
        const std::uint32_t p = incoming[q];
        if (diameter[lower[p]] == 0) continue;
        const Vec3 exchange = share[p] * (v[i] - v[first + lower[p]]);
        o -= exchange;
      }
      if (diameter[k] != 0) {
        Vec3 gain = Vec3::Zero();
        for (std::uint32_t p = pair_start[k]; p < pair_start[k + 1]; ++p) {
          const Vec3 exchange = share[p] * (v[first + upper[p]] - v[i]);
          gain += exchange;
        }
        o += gain;
      }
      out[i] = o;
    }
  });
  exec.for_chunks(count, kParticleChunk, [&](std::size_t b, std::size_t e) {
    for (std::size_t k = b; k < e; ++k)
      v[first + k] = out[first + k];
  });
}

}  // namespace

void smooth_strand_velocities(TissueWorld& world, const physics::Executor& exec) {
  for (const StrandSet& set : world.strands)
    if (set.xsph_coefficient > 0) smooth_set(world, set, exec);
}

void smooth_strand_velocities(TissueWorld& world) {
  const physics::Executor serial(1);
  smooth_strand_velocities(world, serial);
}

}  // namespace imasim::tissue
