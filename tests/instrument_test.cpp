// Instrument kinematics (eq. 14-16): the transform chain, jaw integration, its limits, the
// closed threshold and the jaws' signed opening (upper towards +n, lower towards -n).
#include "surgery/instrument.hpp"

#include <gtest/gtest.h>

namespace imasim::surgery {
namespace {

TEST(Instrument, WorldPoseIsControllerThenLocalThenInitial) {
  InstrumentParams p;
  p.initial.translation = Vec3(0, 0, 0.01);
  InstrumentState s;
  s.controller.rotation = axis_angle(Vec3::UnitY(), kPi / 2);
  s.controller.translation = Vec3(1, 2, 3);
  s.local.rotation = axis_angle(Vec3::UnitX(), kPi / 2);
  const Pose w = world_pose(p, s);  // eq. 15
  // (0, 0, 0.01) -> local: about x by 90 deg -> (0, -0.01, 0); controller: about y -> same
  // (y is the axis), then + (1, 2, 3).
  EXPECT_NEAR((w.translation - Vec3(1, 1.99, 3)).norm(), 0, 1e-15);
  EXPECT_NEAR((w.rotation - s.controller.rotation * s.local.rotation).norm(), 0, 1e-15);
}

TEST(Instrument, JawAngleIntegratesTheButtonRate) {
  const JawParams jaws;
  InstrumentState s;
  const Real dt = 0.001;
  for (int n = 0; n < 100; ++n)
    integrate_jaws(jaws, JawCommand::open, dt, s);
  // eq. 16: theta = 100 dt theta_dot, each step adding the same increment.
  EXPECT_NEAR(s.jaw_angle, 100 * dt * jaws.button_rate, 1e-13);
  integrate_jaws(jaws, JawCommand::hold, dt, s);
  EXPECT_NEAR(s.jaw_angle, 100 * dt * jaws.button_rate, 1e-13);
  for (int n = 0; n < 40; ++n)
    integrate_jaws(jaws, JawCommand::close, dt, s);
  EXPECT_NEAR(s.jaw_angle, 60 * dt * jaws.button_rate, 1e-13);
}

TEST(Instrument, JawAngleStaysInItsRange) {
  const JawParams jaws;
  InstrumentState s;
  for (int n = 0; n < 1000; ++n)
    integrate_jaws(jaws, JawCommand::open, 0.005, s);
  EXPECT_EQ(s.jaw_angle, jaws.max_angle);  // 30 degrees (Fig. 11a)
  EXPECT_NEAR(s.jaw_angle, kPi / 6, 1e-15);
  for (int n = 0; n < 1000; ++n)
    integrate_jaws(jaws, JawCommand::close, 0.005, s);
  EXPECT_EQ(s.jaw_angle, 0);
}

TEST(Instrument, ClosedBelowTwoPointEightSixDegrees) {
  JawParams jaws;
  jaws.button_rate = degrees_to_radians(Real(1)) / 0.01;  // 1 degree per 10 ms step
  InstrumentState s;
  s.jaw_angle = degrees_to_radians(Real(2.5));
  integrate_jaws(jaws, JawCommand::hold, 0.01, s);
  EXPECT_TRUE(s.closed);
  integrate_jaws(jaws, JawCommand::open, 0.01, s);  // 3.5 degrees
  EXPECT_FALSE(s.closed);
  s.jaw_angle = degrees_to_radians(Real(2.86));
  integrate_jaws(jaws, JawCommand::hold, 0.01, s);
  EXPECT_FALSE(s.closed);  // "below" the threshold: 2.86 itself is open
  s.jaw_angle = std::nextafter(degrees_to_radians(Real(2.86)), Real(0));
  integrate_jaws(jaws, JawCommand::hold, 0.01, s);
  EXPECT_TRUE(s.closed);
}

TEST(Instrument, UpperJawOpensTowardsPlusNLowerTowardsMinusN) {
  InstrumentParams p;
  InstrumentState s;
  s.controller.rotation = axis_angle(Vec3(1, 2, 3).normalized(), 0.7);
  s.controller.translation = Vec3(0.1, -0.2, 0.3);
  const Pose w = world_pose(p, s);
  const Vec3 hinge = w.translation, l = w.rotate(Vec3::UnitX()), n = w.rotate(Vec3::UnitY()),
             f = w.rotate(Vec3::UnitZ());
  for (const Real degrees : {Real(5), Real(20), Real(30)}) {
    SCOPED_TRACE(degrees);
    s.jaw_angle = degrees_to_radians(degrees);
    const Real c = std::cos(s.jaw_angle), sn = std::sin(s.jaw_angle), L = p.jaws.length;
    const Vec3 upper = jaw_tip(p, upper_jaw_pose(p, s)) - hinge;
    const Vec3 lower = jaw_tip(p, lower_jaw_pose(p, s)) - hinge;
    // Signed (l, n, f) coordinates of the tips: the upper jaw opens towards +n, the lower
    // towards -n, both in the plane of f and n (the hinge axis is along l).
    EXPECT_NEAR(upper.dot(n), L * sn, 1e-15);
    EXPECT_NEAR(lower.dot(n), -L * sn, 1e-15);
    EXPECT_GT(upper.dot(n), 0);
    EXPECT_LT(lower.dot(n), 0);
    EXPECT_NEAR(upper.dot(f), L * c, 1e-15);
    EXPECT_NEAR(lower.dot(f), L * c, 1e-15);
    EXPECT_NEAR(upper.dot(l), 0, 1e-15);
    EXPECT_NEAR(lower.dot(l), 0, 1e-15);
    // The jaw frames keep the hinge axis and turn f towards +n (upper) and -n (lower).
    const Pose up = upper_jaw_pose(p, s), lo = lower_jaw_pose(p, s);
    EXPECT_NEAR((up.rotate(Vec3::UnitZ()) - (c * f + sn * n)).norm(), 0, 1e-15);
    EXPECT_NEAR((lo.rotate(Vec3::UnitZ()) - (c * f - sn * n)).norm(), 0, 1e-15);
    EXPECT_NEAR((up.rotate(Vec3::UnitX()) - l).norm(), 0, 1e-15);
    EXPECT_NEAR((lo.rotate(Vec3::UnitX()) - l).norm(), 0, 1e-15);
    EXPECT_NEAR(std::acos(upper.normalized().dot(lower.normalized())), 2 * s.jaw_angle, 1e-7);
  }
  // Closed jaws coincide.
  s.jaw_angle = 0;
  EXPECT_NEAR((jaw_tip(p, upper_jaw_pose(p, s)) - jaw_tip(p, lower_jaw_pose(p, s))).norm(), 0,
              1e-15);
}

}  // namespace
}  // namespace imasim::surgery
