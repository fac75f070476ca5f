#pragma once
// Distance constraint (eq. 2): C(p1, p2) = |p1 - p2| - d0.
#include <array>
#include <cmath>
#include <cstdint>

#include "physics/projection.hpp"

namespace imasim::physics {

struct DistanceRow {
  std::uint32_t i = 0, j = 0;
  Real rest_length = 0;  // d0 (unit: m)
  // This row's compliance is its material's times this (dimensionless): a membrane's material
  // holds 1/(E t) and each edge its share of the mesh (physics/membrane_material.hpp).
  Real compliance_scale = 1;
  MaterialId material = 0;
  std::uint32_t slot = 0;
  using Lambda = Real;  // back-reference for handle bookkeeping

  std::array<std::uint32_t, 2> particles() const { return {i, j}; }
};

// Value and gradient, for any scalar (tests check them in double against finite differences).
template <class S>
struct DistanceEval {
  using V = Eigen::Matrix<S, 3, 1>;
  S value = 0;  // C (unit: m)
  V grad_i = V::Zero(), grad_j = V::Zero();
  bool valid = false;  // false when the particles coincide (direction undefined)
};

template <class S>
DistanceEval<S> evaluate_distance(const Eigen::Matrix<S, 3, 1>& pi,
                                  const Eigen::Matrix<S, 3, 1>& pj, S rest_length) {
  DistanceEval<S> e;
  const Eigen::Matrix<S, 3, 1> d = pi - pj;
  const S len = d.norm();
  e.value = len - rest_length;
  if (!(len > S(1e-12))) return e;
  e.grad_i = d / len;
  e.grad_j = -e.grad_i;
  e.valid = true;
  return e;
}

inline void project_distance(const DistanceRow& r, Real& lambda, const ProjectionContext& ctx) {
  const Real wi = ctx.inverse_mass[r.i], wj = ctx.inverse_mass[r.j];
  const Real w = wi + wj;
  if (w == 0) return;
  Vec3& pi = ctx.positions[r.i];
  Vec3& pj = ctx.positions[r.j];
  const Vec3 d = pi - pj;
  const Real len = d.norm();
  if (!(len > Real(1e-12))) return;
  // grad_i C = n, grad_j C = -n, |grad|^2 = 1 each. One division and three products instead of
  // three divisions: this projection is two fifths of a session's step, and its divisions were
  // a tenth of the solve (docs/PERFORMANCE.md).
  const Vec3 n = d * (Real(1) / len);
  const Real dl = lambda_increment(scaled(ctx.terms[r.material], r.compliance_scale),
                                   len - r.rest_length, w, lambda);
  lambda += dl;
  pi += (wi * dl) * n;
  pj -= (wj * dl) * n;
}

}  // namespace imasim::physics
