#pragma once
// A rigid transform x -> R x + t (R a rotation, t in m).
#include "math/types.hpp"

namespace imasim {

struct Pose {
  Mat3 rotation = Mat3::Identity();
  Vec3 translation = Vec3::Zero();

  Vec3 apply(const Vec3& x) const { return rotation * x + translation; }
  Vec3 rotate(const Vec3& v) const { return rotation * v; }
  friend Pose operator*(const Pose& a, const Pose& b) {
    return {a.rotation * b.rotation, a.rotation * b.translation + a.translation};
  }
};

// Rotation by `angle` (rad) about the unit `axis`.
inline Mat3 axis_angle(const Vec3& axis, Real angle) {
  return Eigen::AngleAxis<Real>(angle, axis.normalized()).toRotationMatrix();
}

}  // namespace imasim
