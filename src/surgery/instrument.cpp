#include "surgery/instrument.hpp"

#include <algorithm>

namespace imasim::surgery {

void integrate_jaws(const JawParams& jaws, JawCommand command, Real dt, InstrumentState& s) {
  const Real rate = Real(static_cast<int>(command)) * jaws.button_rate;        // theta_dot (rad/s)
  s.jaw_angle = std::clamp(s.jaw_angle + rate * dt, Real(0), jaws.max_angle);  // eq. 16
  s.closed = s.jaw_angle < jaws.closed_threshold;
}

namespace {

Pose jaw_pose(const InstrumentParams& p, const InstrumentState& s, Real angle) {
  Pose turn;
  turn.rotation = axis_angle(p.jaws.hinge_axis, angle);  // R(theta, alpha)
  return world_pose(p, s) * turn;
}

}  // namespace

Pose upper_jaw_pose(const InstrumentParams& p, const InstrumentState& s) {
  return jaw_pose(p, s, s.jaw_angle);
}

Pose lower_jaw_pose(const InstrumentParams& p, const InstrumentState& s) {
  return jaw_pose(p, s, -s.jaw_angle);
}

Vec3 jaw_tip(const InstrumentParams& p, const Pose& jaw) {
  return jaw.apply(Vec3(0, 0, p.jaws.length));
}

}  // namespace imasim::surgery
