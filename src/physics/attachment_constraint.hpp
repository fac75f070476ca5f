#pragma once
// Attachment of a particle to a moving target point (grasping, anchoring): three linear rows,
// C_k(p) = p_k - t_k (k = x, y, z), each with its own multiplier. Unlike the norm |p - t| its
// gradients (the unit axes) are defined everywhere, at the target too, and with one isotropic
// compliance the three rows are independent, so one projection solves them exactly.
#include <array>
#include <cstdint>

#include "physics/projection.hpp"

namespace imasim::physics {

struct AttachmentRow {
  std::uint32_t i = 0;
  MaterialId material = 0;
  std::uint32_t slot = 0;
  using Lambda = Vec3;         // one multiplier per axis
  Vec3 target = Vec3::Zero();  // (unit: m)

  std::array<std::uint32_t, 1> particles() const { return {i}; }
};

// The rows' values C = p - t (unit: m); their gradients are the unit axes.
template <class S>
Eigen::Matrix<S, 3, 1> attachment_values(const Eigen::Matrix<S, 3, 1>& p,
                                         const Eigen::Matrix<S, 3, 1>& target) {
  return p - target;
}

// XPBD on the three rows at once: d_lambda = (-C - alpha~ lambda) / (w + alpha~), x += w d_lambda.
inline void project_attachment(const AttachmentRow& r, Vec3& lambda, const ProjectionContext& ctx) {
  const Real w = ctx.inverse_mass[r.i];
  if (w == 0) return;
  Vec3& p = ctx.positions[r.i];
  const ProjectionTerms& t = ctx.terms[r.material];
  const Vec3 dl = (-t.scale * (p - r.target) - t.alpha_tilde * lambda) / (w + t.alpha_tilde);
  lambda += dl;
  p += w * dl;
}

}  // namespace imasim::physics
