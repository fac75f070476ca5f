#pragma once
// Projection of a batch of dihedral constraints of one colour at once, one constraint per SIMD
// lane: the same arithmetic as project_dihedral (dihedral_constraint.hpp), laid out so that the
// long dependent chain of one constraint overlaps with its neighbours'. Rows of one colour share
// no particle, so gathering them, projecting together and scattering back equals projecting
// them one after another.
#include <cstddef>

#include "physics/dihedral_constraint.hpp"
#include "physics/simd.hpp"

namespace imasim::physics {

inline constexpr std::size_t kDihedralBatch = simd::kLanes<Real>;

// Projects rows[0 .. kDihedralBatch).
inline void project_dihedral_batch(const DihedralRow* rows, Real* lambda,
                                   const ProjectionContext& ctx) {
  using S = Real;
  using VS = simd::V<S>;
  using V3 = simd::V3<S>;
  constexpr std::size_t L = kDihedralBatch;
  Vec3* x = ctx.positions;
  const Real* w = ctx.inverse_mass;

  // Gather, relative to the edge start p2 (smaller numbers, fewer operations).
  V3 a0, a1, e;
  VS w0, w1, w2, w3, rc, rs, scale, alpha, lam;
  for (std::size_t k = 0; k < L; ++k) {
    const DihedralRow& r = rows[k];
    const Vec3& o = x[r.p[2]];
    const Vec3 d0 = x[r.p[0]] - o, d1 = x[r.p[1]] - o, d3 = x[r.p[3]] - o;
    a0.x[k] = d0.x(), a0.y[k] = d0.y(), a0.z[k] = d0.z();
    a1.x[k] = d1.x(), a1.y[k] = d1.y(), a1.z[k] = d1.z();
    e.x[k] = d3.x(), e.y[k] = d3.y(), e.z[k] = d3.z();
    w0[k] = w[r.p[0]], w1[k] = w[r.p[1]], w2[k] = w[r.p[2]], w3[k] = w[r.p[3]];
    rc[k] = r.rest_cos, rs[k] = r.rest_sin;
    const ProjectionTerms& t = ctx.terms[r.material];
    scale[k] = t.scale, alpha[k] = t.alpha_tilde * r.compliance_scale;
    lam[k] = lambda[k];
  }

  // Geometry (dihedral_geometry with p2 at the origin): N1 = (p2-p0) x (p3-p0), N2 =
  // (p3-p1) x (p2-p1).
  const VS ee = simd::dot(e, e);
  const V3 n1 = simd::cross(V3{-a0.x, -a0.y, -a0.z}, e - a0);
  const V3 n2 = simd::cross(e - a1, V3{-a1.x, -a1.y, -a1.z});
  const VS n1sq = simd::dot(n1, n1), n2sq = simd::dot(n2, n2);
  const VS limit = S(kDegenerateHeightRatio * kDegenerateHeightRatio) * ee * ee;
  auto valid = (ee > S(1e-24)) & (n1sq > limit) & (n2sq > limit) & (w0 + w1 + w2 + w3 > 0);
  // Invalid lanes compute on harmless values and are discarded by the mask below.
  const VS one = simd::splat<S>(1);
  const VS inv1 = one / (valid ? n1sq : one), inv2 = one / (valid ? n2sq : one);
  const VS inv_ee = one / (valid ? ee : one);
  const VS le = simd::sqrt<S>(ee);
  const VS n12 = simd::dot(n1, n2);
  const VS sin_s = simd::dot(simd::cross(n1, n2), e), cos_s = le * n12;
  const VS ys = sin_s * rc - cos_s * rs, xs = cos_s * rc + sin_s * rs;

  // atan2_near_zero: the series where |y| <= x/8, libm elsewhere (rare for bending).
  const auto near = (xs > 0) & (simd::abs<S>(ys) <= S(0.125) * xs);
  const VS t = ys / (near ? xs : one), t2 = t * t;
  VS series = simd::splat<S>(S(1) / S(17));
  for (const S c : {S(-1) / S(15), S(1) / S(13), S(-1) / S(11), S(1) / S(9), S(-1) / S(7),
                    S(1) / S(5), S(-1) / S(3), S(1)}) {
    series = series * t2 + c;
  }
  VS value = t * series;
  for (std::size_t k = 0; k < L; ++k) {
    if (!near[k] && valid[k]) value[k] = std::atan2(ys[k], xs[k]);
  }

  const VS t0 = simd::dot(a0, e) * inv_ee, t1 = simd::dot(a1, e) * inv_ee;
  const VS g00 = ee * inv1, g11 = ee * inv2, g01 = ee * n12 * inv1 * inv2;
  const VS c0 = t0 - 1, c1 = t1 - 1;
  const VS wg = w0 * g00 + w1 * g11 + w2 * (c0 * c0 * g00 + c1 * c1 * g11 + 2 * c0 * c1 * g01) +
                w3 * (t0 * t0 * g00 + t1 * t1 * g11 + 2 * t0 * t1 * g01);
  valid = valid & (wg > S(1e-30));
  const VS dl_raw = (-scale * value - alpha * lam) / (valid ? wg + alpha : one);
  const VS dl = valid ? dl_raw : simd::splat<S>(0);
  lam += dl;
  const V3 d0 = (-le * inv1 * dl) * n1;  // dl * grad_0
  const V3 d1 = (-le * inv2 * dl) * n2;  // dl * grad_1
  const V3 u2 = c0 * d0 + c1 * d1;       // dl * grad_2
  const V3 u3 = t0 * d0 + t1 * d1;       // -dl * grad_3

  for (std::size_t k = 0; k < L; ++k) {
    lambda[k] = lam[k];
    if (!valid[k]) continue;
    const DihedralRow& r = rows[k];
    // Written out per component (the same arithmetic as x += w * Vec3(...)): GCC stopped
    // inlining Eigen's loop for that here once step.cpp grew, a call per row that made the
    // cloth's step 28 % slower (docs/PERFORMANCE.md).
    Real* x0 = x[r.p[0]].data();
    Real* x1 = x[r.p[1]].data();
    Real* x2 = x[r.p[2]].data();
    Real* x3 = x[r.p[3]].data();
    x0[0] += w0[k] * d0.x[k], x0[1] += w0[k] * d0.y[k], x0[2] += w0[k] * d0.z[k];
    x1[0] += w1[k] * d1.x[k], x1[1] += w1[k] * d1.y[k], x1[2] += w1[k] * d1.z[k];
    x2[0] += w2[k] * u2.x[k], x2[1] += w2[k] * u2.y[k], x2[2] += w2[k] * u2.z[k];
    x3[0] -= w3[k] * u3.x[k], x3[1] -= w3[k] * u3.y[k], x3[2] -= w3[k] * u3.z[k];
  }
}

}  // namespace imasim::physics
