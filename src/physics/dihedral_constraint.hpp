#pragma once
// Dihedral (bending) constraint (eq. 3), the signed atan2 form:
//   C = atan2((n1 x n2) . e, |e| n1 . n2) - theta_rest,   e = p3 - p2
// on two triangles (p0, p2, p3) and (p1, p3, p2) that share the edge p2-p3; p0 and p1 are the
// wing vertices. n1 ~ (p2 - p0) x (p3 - p0), n2 ~ (p3 - p1) x (p2 - p1).
// Sign: the angle is 0 for a flat pair and positive when the wings fold away from the side the
// normals point to (a ridge seen from the normal side), negative when they fold towards it.
// C is wrapped to (-pi, pi] so that the constraint takes the short way round near +-pi.
#include <array>
#include <cmath>
#include <cstdint>

#include "math/angles.hpp"
#include "physics/projection.hpp"

namespace imasim::physics {

struct DihedralRow {
  std::array<std::uint32_t, 4> p = {0, 0, 0, 0};  // wing0, wing1, edge start, edge end
  Real rest_angle = 0;  // theta_rest (unit: rad), measured on the rest mesh
  MaterialId material = 0;
  std::uint32_t slot = 0;

  const std::array<std::uint32_t, 4>& particles() const { return p; }
};

struct DihedralEval {
  Real value = 0;  // C (unit: rad)
  std::array<Vec3, 4> grad = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  bool valid = false;  // false for a degenerate triangle or a zero-length shared edge
};

// A triangle whose height over the shared edge is below this fraction of the edge length is
// treated as degenerate: its normal, and so the angle, is undefined there.
inline constexpr Real kDegenerateHeightRatio = Real(1e-6);

// Value and exact gradient. With unnormalised normals N1, N2, the wing gradients are
// -|e| N/|N|^2 (a wing at height |N|/|e| over the edge turns its face by 1/height per unit of
// motion along N); the edge vertices share the opposite of the wing gradients in proportion to
// where each wing projects on the edge, so that the gradients sum to zero (translation
// invariance) and exert no net moment (rotation invariance).
inline DihedralEval evaluate_dihedral(const Vec3& p0, const Vec3& p1, const Vec3& p2,
                                      const Vec3& p3, Real rest_angle) {
  DihedralEval r;
  const Vec3 e = p3 - p2;
  const Real ee = e.squaredNorm();
  if (!(ee > Real(1e-24))) return r;
  const Vec3 n1 = (p2 - p0).cross(p3 - p0);
  const Vec3 n2 = (p3 - p1).cross(p2 - p1);
  const Real n1sq = n1.squaredNorm(), n2sq = n2.squaredNorm();
  const Real limit = kDegenerateHeightRatio * kDegenerateHeightRatio * ee * ee;
  if (!(n1sq > limit) || !(n2sq > limit)) return r;
  const Real le = std::sqrt(ee);
  // Both atan2 arguments carry the common factor |N1||N2| > 0, which does not change the angle.
  const Real angle = std::atan2(n1.cross(n2).dot(e), le * n1.dot(n2));
  r.value = wrap_angle(angle - rest_angle);
  r.grad[0] = (-le / n1sq) * n1;
  r.grad[1] = (-le / n2sq) * n2;
  const Real t0 = (p0 - p2).dot(e) / ee;
  const Real t1 = (p1 - p2).dot(e) / ee;
  r.grad[2] = (t0 - 1) * r.grad[0] + (t1 - 1) * r.grad[1];
  r.grad[3] = -t0 * r.grad[0] - t1 * r.grad[1];
  r.valid = true;
  return r;
}

// The signed dihedral angle itself (unit: rad); 0 when degenerate.
inline Real dihedral_angle(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3) {
  return evaluate_dihedral(p0, p1, p2, p3, Real(0)).value;
}

inline void project_dihedral(const DihedralRow& r, Real& lambda, const ProjectionContext& ctx) {
  const Real* w = ctx.inverse_mass;
  const Real w0 = w[r.p[0]], w1 = w[r.p[1]], w2 = w[r.p[2]], w3 = w[r.p[3]];
  if (w0 + w1 + w2 + w3 == 0) return;
  Vec3* x = ctx.positions;
  const DihedralEval e =
      evaluate_dihedral(x[r.p[0]], x[r.p[1]], x[r.p[2]], x[r.p[3]], r.rest_angle);
  if (!e.valid) return;
  const Real wg = w0 * e.grad[0].squaredNorm() + w1 * e.grad[1].squaredNorm() +
                  w2 * e.grad[2].squaredNorm() + w3 * e.grad[3].squaredNorm();
  if (!(wg > Real(1e-30))) return;
  const Real dl = lambda_increment(ctx.terms[r.material], e.value, wg, lambda);
  lambda += dl;
  x[r.p[0]] += (w0 * dl) * e.grad[0];
  x[r.p[1]] += (w1 * dl) * e.grad[1];
  x[r.p[2]] += (w2 * dl) * e.grad[2];
  x[r.p[3]] += (w3 * dl) * e.grad[3];
}

}  // namespace imasim::physics
