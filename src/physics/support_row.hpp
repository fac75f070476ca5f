#pragma once
// A particle held to a fixed base by a soft column (the fat under the fascia and the vessel,
// tissue/fat_support.hpp): C(x) = n . x - offset, the plane through the particle's rest position
// normal to the column, with the column's compliance 1/k. Gathered before each step by the
// tissue's owner, projected in the particle's band after its constraint sweeps, before the
// contacts (which have the last word). A column that pushes only (C >= 0, an XPBD inequality:
// the substep's multiplier is kept a push, lambda >= 0) never pulls its particle back; one that
// does not holds it both ways.
#include <cstdint>

#include "math/types.hpp"

namespace imasim::physics {

struct SupportRow {
  std::uint32_t particle = 0;
  Vec3 normal = Vec3::UnitY();  // unit, away from the base
  Real offset = 0;              // the plane: n . x = offset (unit: m)
  Real compliance = 0;          // 1 / k, k the column's stiffness (unit: m/N)
  Real lambda = 0;              // the substep's multiplier (unit: N s^2)
  Real impulse = 0;             // the push over the step, a pull negative (unit: N s)
  bool pushes_only = true;
};

// One projection in a substep of length h (unit: s): d_lambda = (-C - alpha~ lambda) / (w +
// alpha~), alpha~ = compliance / h^2; clamped so that lambda stays >= 0 if it pushes only.
inline void project_support(SupportRow& r, Vec3* p, const Real* w, Real h) {
  const Real wi = w[r.particle];
  if (wi == 0) return;
  Vec3& x = p[r.particle];
  const Real c = r.normal.dot(x) - r.offset;
  if (r.pushes_only && c >= 0 && r.lambda == 0) return;  // uncompressed and not pushing
  const Real alpha_tilde = r.compliance / (h * h);
  Real d_lambda = (-c - alpha_tilde * r.lambda) / (wi + alpha_tilde);
  if (r.pushes_only && r.lambda + d_lambda < 0) d_lambda = -r.lambda;
  r.lambda += d_lambda;
  x += (wi * d_lambda) * r.normal;
  r.impulse += d_lambda / h;  // the substep's force is lambda / h^2, over h
}

}  // namespace imasim::physics
