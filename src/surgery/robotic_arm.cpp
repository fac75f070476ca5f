#include "surgery/robotic_arm.hpp"

#include <algorithm>
#include <cmath>

namespace imasim::surgery {

Mat3 frame_along(const Vec3& f) {
  Vec3 l = Vec3::UnitZ().cross(f);
  if (l.norm() < Real(1e-6)) l = Vec3::UnitX().cross(f);
  l.normalize();
  Mat3 r;
  r.col(0) = l;
  r.col(1) = f.cross(l);
  r.col(2) = f;
  return r;
}

Pose constrain_to_port(const ArmParams& a, const Pose& commanded) {
  Pose out = commanded;
  Vec3 along = commanded.translation - a.port;
  Real depth = along.norm();
  // A hinge on the port itself has no shaft direction: keep the orientation's f axis.
  const Vec3 axis =
      depth > Real(1e-9) ? Vec3(along / depth) : Vec3(commanded.rotate(Vec3::UnitZ()));
  depth = std::clamp(depth, a.min_insertion, a.max_insertion);
  out.translation = a.port + depth * axis;

  const Vec3 f = commanded.rotate(Vec3::UnitZ());
  const Real angle = std::atan2(f.cross(axis).norm(), f.dot(axis));
  if (angle > a.wrist_limit) {
    Vec3 turn_axis = f.cross(axis);
    if (!(turn_axis.norm() > Real(1e-12))) {  // f opposite the shaft: any normal axis will do
      turn_axis = f.unitOrthogonal();
    }
    out.rotation = axis_angle(turn_axis.normalized(), angle - a.wrist_limit) * commanded.rotation;
  }
  return out;
}

ArmState make_arm_state(const ArmParams& a, const Pose& start, const Pose& hand) {
  ArmState s;
  s.hand_anchor = hand;
  s.tool = constrain_to_port(a, start);
  s.tool_anchor = s.tool;
  s.commanded = s.tool;
  return s;
}

void update_arm(const ArmParams& a, const Pose& hand, bool clutch, ArmState& s) {
  if (clutch) {
    s.clutched = true;
    return;  // the tool holds; the hand moves freely
  }
  if (s.clutched) {  // released: continue from here
    s.clutched = false;
    s.hand_anchor = hand;
    s.tool_anchor = s.tool;
  }
  // Scaled translation, unscaled rotation, both relative to the anchors.
  const Vec3 moved = hand.translation - s.hand_anchor.translation;
  const Mat3 turned = hand.rotation * s.hand_anchor.rotation.transpose();
  s.commanded.translation = s.tool_anchor.translation + a.motion_scale * moved;
  s.commanded.rotation = turned * s.tool_anchor.rotation;
  s.tool = constrain_to_port(a, s.commanded);
}

Vec3 shaft_direction(const ArmParams& a, const ArmState& s) {
  return (s.tool.translation - a.port).normalized();
}

}  // namespace imasim::surgery
