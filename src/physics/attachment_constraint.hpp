#pragma once
// Attachment of a particle to a moving target point (grasping, anchoring):
// C(p) = |p - t|, a zero-length distance constraint to a point that the caller moves.
#include <array>
#include <cstdint>

#include "physics/projection.hpp"

namespace imasim::physics {

struct AttachmentRow {
  std::uint32_t i = 0;
  MaterialId material = 0;
  std::uint32_t slot = 0;
  Vec3 target = Vec3::Zero();  // (unit: m)

  std::array<std::uint32_t, 1> particles() const { return {i}; }
};

template <class S>
struct AttachmentEval {
  using V = Eigen::Matrix<S, 3, 1>;
  S value = 0;  // C (unit: m)
  V grad = V::Zero();
  bool valid = false;  // false when p is on the target (C = 0, direction undefined)
};

template <class S>
AttachmentEval<S> evaluate_attachment(const Eigen::Matrix<S, 3, 1>& p,
                                      const Eigen::Matrix<S, 3, 1>& target) {
  AttachmentEval<S> e;
  const Eigen::Matrix<S, 3, 1> d = p - target;
  e.value = d.norm();
  if (!(e.value > S(1e-12))) return e;
  e.grad = d / e.value;
  e.valid = true;
  return e;
}

inline void project_attachment(const AttachmentRow& r, Real& lambda, const ProjectionContext& ctx) {
  const Real w = ctx.inverse_mass[r.i];
  if (w == 0) return;
  Vec3& p = ctx.positions[r.i];
  const Vec3 d = p - r.target;
  const Real len = d.norm();
  if (!(len > Real(1e-12))) return;
  const Real dl = lambda_increment(ctx.terms[r.material], len, w, lambda);
  lambda += dl;
  p += (w * dl / len) * d;
}

}  // namespace imasim::physics
