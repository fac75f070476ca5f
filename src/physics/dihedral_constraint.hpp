#pragma once
// Dihedral (bending) constraint (eq. 3), the signed atan2 form:
//   C = atan2((n1 x n2) . e, |e| n1 . n2) - theta_rest,   e = p3 - p2
// on two triangles (p0, p2, p3) and (p1, p3, p2) that share the edge p2-p3; p0 and p1 are the
// wing vertices. n1 ~ (p2 - p0) x (p3 - p0), n2 ~ (p3 - p1) x (p2 - p1).
// Sign: the angle is 0 for a flat pair and positive when the wings fold away from the side the
// normals point to (a ridge seen from the normal side), negative when they fold towards it.
// C is in (-pi, pi]: the constraint takes the short way round near +-pi.
#include <array>
#include <cmath>
#include <cstdint>

#include "math/angles.hpp"
#include "physics/projection.hpp"

namespace imasim::physics {

struct DihedralRow {
  std::array<std::uint32_t, 4> p = {0, 0, 0, 0};  // wing0, wing1, edge start, edge end
  // theta_rest, measured on the rest mesh, kept as its cosine and sine: C is then the angle of
  // the measured (cos, sin) pair rotated by -theta_rest, which needs no wrapping (see below).
  Real rest_cos = 1;
  Real rest_sin = 0;
  Real compliance_scale = 1;  // dimensionless, as DistanceRow's
  MaterialId material = 0;
  std::uint32_t slot = 0;
  using Lambda = Real;

  const std::array<std::uint32_t, 4>& particles() const { return p; }
  Real rest_angle() const { return std::atan2(rest_sin, rest_cos); }  // (unit: rad)
};

// atan2(y, x). Near zero (x > 0, |y| <= x/8), where a bending constraint spends its life, the
// odd Taylor series of atan through t^17 is exact to double rounding (the first omitted term,
// t^19/19, is below 2^-57 t) and several times cheaper than libm's atan2.
template <class S>
S atan2_near_zero(S y, S x) {
  if (x > 0 && std::abs(y) <= S(0.125) * x) {
    const S t = y / x, t2 = t * t;
    S s = S(1) / S(17);
    for (const S c : {S(-1) / S(15), S(1) / S(13), S(-1) / S(11), S(1) / S(9), S(-1) / S(7),
                      S(1) / S(5), S(-1) / S(3), S(1)}) {
      s = s * t2 + c;
    }
    return t * s;
  }
  return std::atan2(y, x);
}

// The quantities that both the value/gradient and the projection need. rest_cos and rest_sin
// may be any positive multiple of (cos, sin) of the rest angle.
template <class S>
struct DihedralGeometry {
  Eigen::Matrix<S, 3, 1> n1, n2;  // unnormalised face normals N1, N2
  S inv_n1sq, inv_n2sq;           // 1/|N1|^2, 1/|N2|^2
  S ee, le;                       // |e|^2, |e|
  S t0, t1;    // where each wing projects on the edge, as a fraction of e from p2
  S value;     // C (unit: rad)
  bool valid;  // false for a degenerate triangle or a zero-length shared edge
};

// A triangle whose height over the shared edge is below this fraction of the edge length is
// treated as degenerate: its normal, and so the angle, is undefined there.
inline constexpr double kDegenerateHeightRatio = 1e-6;

template <class S>
DihedralGeometry<S> dihedral_geometry(const Eigen::Matrix<S, 3, 1>& p0,
                                      const Eigen::Matrix<S, 3, 1>& p1,
                                      const Eigen::Matrix<S, 3, 1>& p2,
                                      const Eigen::Matrix<S, 3, 1>& p3, S rest_cos, S rest_sin) {
  DihedralGeometry<S> g;
  const Eigen::Matrix<S, 3, 1> e = p3 - p2;
  g.ee = e.squaredNorm();
  g.valid = false;
  g.value = 0;
  if (!(g.ee > S(1e-24))) return g;
  g.n1 = (p2 - p0).cross(p3 - p0);
  g.n2 = (p3 - p1).cross(p2 - p1);
  const S n1sq = g.n1.squaredNorm(), n2sq = g.n2.squaredNorm();
  const S limit = S(kDegenerateHeightRatio * kDegenerateHeightRatio) * g.ee * g.ee;
  if (!(n1sq > limit) || !(n2sq > limit)) return g;
  // Divisions are the expensive part of a projection: three reciprocals serve them all.
  g.inv_n1sq = S(1) / n1sq;
  g.inv_n2sq = S(1) / n2sq;
  const S inv_ee = S(1) / g.ee;
  g.le = std::sqrt(g.ee);
  // sin and cos of the angle, both scaled by |N1||N2| > 0 (which atan2 ignores), then rotated
  // by -theta_rest so that atan2 returns theta - theta_rest already in (-pi, pi].
  const S sin_scaled = g.n1.cross(g.n2).dot(e);
  const S cos_scaled = g.le * g.n1.dot(g.n2);
  g.value = atan2_near_zero(sin_scaled * rest_cos - cos_scaled * rest_sin,
                            cos_scaled * rest_cos + sin_scaled * rest_sin);
  g.t0 = (p0 - p2).dot(e) * inv_ee;
  g.t1 = (p1 - p2).dot(e) * inv_ee;
  g.valid = true;
  return g;
}

template <class S>
struct DihedralEval {
  using V = Eigen::Matrix<S, 3, 1>;
  S value = 0;  // C (unit: rad)
  std::array<V, 4> grad = {V::Zero(), V::Zero(), V::Zero(), V::Zero()};
  bool valid = false;
};

// Value and exact gradient. The wing gradients are -|e| N/|N|^2 (a wing at height |N|/|e| over
// the edge turns its face by 1/height per unit of motion along N); the edge vertices share the
// opposite of the wing gradients in proportion to where each wing projects on the edge, so that
// the gradients sum to zero (translation invariance) and exert no net moment (rotation
// invariance).
// rest_cos, rest_sin: of the rest angle (a caller evaluating the same row often keeps them).
template <class S>
DihedralEval<S> evaluate_dihedral(const Eigen::Matrix<S, 3, 1>& p0,
                                  const Eigen::Matrix<S, 3, 1>& p1,
                                  const Eigen::Matrix<S, 3, 1>& p2,
                                  const Eigen::Matrix<S, 3, 1>& p3, S rest_cos, S rest_sin) {
  const DihedralGeometry<S> g = dihedral_geometry(p0, p1, p2, p3, rest_cos, rest_sin);
  DihedralEval<S> r;
  if (!g.valid) return r;
  r.value = g.value;
  r.grad[0] = (-g.le * g.inv_n1sq) * g.n1;
  r.grad[1] = (-g.le * g.inv_n2sq) * g.n2;
  r.grad[2] = (g.t0 - 1) * r.grad[0] + (g.t1 - 1) * r.grad[1];
  r.grad[3] = -g.t0 * r.grad[0] - g.t1 * r.grad[1];
  r.valid = true;
  return r;
}

template <class S>
DihedralEval<S> evaluate_dihedral(const Eigen::Matrix<S, 3, 1>& p0,
                                  const Eigen::Matrix<S, 3, 1>& p1,
                                  const Eigen::Matrix<S, 3, 1>& p2,
                                  const Eigen::Matrix<S, 3, 1>& p3, S rest_angle) {
  return evaluate_dihedral(p0, p1, p2, p3, S(std::cos(rest_angle)), S(std::sin(rest_angle)));
}

// The signed dihedral angle itself (unit: rad); 0 when degenerate.
template <class S>
S dihedral_angle(const Eigen::Matrix<S, 3, 1>& p0, const Eigen::Matrix<S, 3, 1>& p1,
                 const Eigen::Matrix<S, 3, 1>& p2, const Eigen::Matrix<S, 3, 1>& p3) {
  return dihedral_geometry(p0, p1, p2, p3, S(1), S(0)).value;
}

// One projection. Same gradients as evaluate_dihedral, with sum_i w_i |grad_i C|^2 formed from
// scalars: |g0|^2 = e.e/|N1|^2, |g1|^2 = e.e/|N2|^2, g0.g1 = e.e (N1.N2)/(|N1|^2 |N2|^2).
inline void project_dihedral(const DihedralRow& r, Real& lambda, const ProjectionContext& ctx) {
  const Real* w = ctx.inverse_mass;
  const Real w0 = w[r.p[0]], w1 = w[r.p[1]], w2 = w[r.p[2]], w3 = w[r.p[3]];
  if (w0 + w1 + w2 + w3 == 0) return;
  Vec3* x = ctx.positions;
  const DihedralGeometry<Real> g =
      dihedral_geometry(x[r.p[0]], x[r.p[1]], x[r.p[2]], x[r.p[3]], r.rest_cos, r.rest_sin);
  if (!g.valid) return;
  const Real g00 = g.ee * g.inv_n1sq, g11 = g.ee * g.inv_n2sq;
  const Real g01 = g.ee * g.n1.dot(g.n2) * g.inv_n1sq * g.inv_n2sq;
  const Real a0 = g.t0 - 1, a1 = g.t1 - 1;  // g2 = a0 g0 + a1 g1, g3 = -t0 g0 - t1 g1
  const Real wg = w0 * g00 + w1 * g11 + w2 * (a0 * a0 * g00 + a1 * a1 * g11 + 2 * a0 * a1 * g01) +
                  w3 * (g.t0 * g.t0 * g00 + g.t1 * g.t1 * g11 + 2 * g.t0 * g.t1 * g01);
  if (!(wg > Real(1e-30))) return;
  const Real dl =
      lambda_increment(scaled(ctx.terms[r.material], r.compliance_scale), g.value, wg, lambda);
  lambda += dl;
  const Vec3 d0 = (-g.le * g.inv_n1sq * dl) * g.n1;  // dl * g0
  const Vec3 d1 = (-g.le * g.inv_n2sq * dl) * g.n2;  // dl * g1
  x[r.p[0]] += w0 * d0;
  x[r.p[1]] += w1 * d1;
  x[r.p[2]] += w2 * (a0 * d0 + a1 * d1);
  x[r.p[3]] -= w3 * (g.t0 * d0 + g.t1 * d1);
}

}  // namespace imasim::physics
