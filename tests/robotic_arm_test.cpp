// The robotic arm: the shaft passes through its port for any commanded pose, hand motion is
// scaled, rotation is not, and the clutch holds the instrument while the hand re-centres.
#include "surgery/robotic_arm.hpp"

#include <gtest/gtest.h>

#include "tissue/random.hpp"

namespace imasim::surgery {
namespace {

ArmParams arm() {
  ArmParams a;
  a.port = Vec3(0.1, -0.05, 0.08);
  return a;
}

// Distance from the port to the line through the hinge along the shaft direction.
Real port_off_shaft(const ArmParams& a, const ArmState& s) {
  const Vec3 d = shaft_direction(a, s);
  const Vec3 r = a.port - s.tool.translation;
  return (r - r.dot(d) * d).norm();
}

TEST(RoboticArm, ShaftPassesThroughThePortForAnyCommand) {
  const ArmParams a = arm();
  tissue::SplitMix64 rng(5);
  auto u = [&] { return 2 * rng.uniform() - 1; };
  for (int n = 0; n < 2000; ++n) {
    Pose command;
    command.translation = a.port + Vec3(u(), u(), u()) * 0.4;  // anywhere, even behind the port
    command.rotation = axis_angle(Vec3(u(), u(), u()).normalized(), 3 * u());
    const Pose tool = constrain_to_port(a, command);
    ArmState s;
    s.tool = tool;
    ASSERT_LT(port_off_shaft(a, s), 1e-15);
    const Real depth = (tool.translation - a.port).norm();
    ASSERT_GE(depth, a.min_insertion - 1e-15);
    ASSERT_LE(depth, a.max_insertion + 1e-15);
    // The jaws' axis stays within the wrist's reach of the shaft.
    const Vec3 f = tool.rotate(Vec3::UnitZ());
    ASSERT_LE(std::acos(std::clamp(f.dot(shaft_direction(a, s)), Real(-1), Real(1))),
              a.wrist_limit + 1e-9);
    ASSERT_NEAR((tool.rotation.transpose() * tool.rotation - Mat3::Identity()).norm(), 0, 1e-14);
  }
}

TEST(RoboticArm, HandMotionIsScaledThreeToOneAndRotationIsNot) {
  const ArmParams a = arm();
  Pose start;
  start.translation = a.port + Vec3(-0.05, 0.02, 0.03);
  // Aim the tool along the shaft so the wrist limit does not act: turn z onto the shaft.
  const Vec3 shaft = (start.translation - a.port).normalized();
  start.rotation =
      axis_angle(Vec3::UnitZ().cross(shaft).normalized(), std::acos(Vec3::UnitZ().dot(shaft)));
  Pose hand;
  hand.translation = Vec3(0.3, 0.3, 0.3);
  ArmState s = make_arm_state(a, start, hand);
  Pose moved = hand;
  moved.translation += Vec3(0.03, -0.015, 0.006);
  moved.rotation = axis_angle(Vec3::UnitY(), 0.2) * hand.rotation;
  update_arm(a, moved, false, s);
  EXPECT_NEAR((s.commanded.translation - start.translation - Vec3(0.01, -0.005, 0.002)).norm(), 0,
              1e-15);
  EXPECT_NEAR((s.commanded.rotation - axis_angle(Vec3::UnitY(), 0.2) * start.rotation).norm(), 0,
              1e-15);
}

TEST(RoboticArm, ClutchHoldsTheInstrumentWhileTheHandRecentres) {
  const ArmParams a = arm();
  Pose start;
  start.translation = a.port + Vec3(-0.05, 0.02, 0.03);
  Pose hand;
  ArmState s = make_arm_state(a, start, hand);
  const Pose before = s.tool;
  Pose away = hand;
  away.translation += Vec3(0.2, -0.1, 0.05);  // the hand goes far while clutched
  away.rotation = axis_angle(Vec3::UnitX(), 1.0);
  update_arm(a, away, true, s);
  EXPECT_EQ(s.tool.translation, before.translation);
  EXPECT_EQ(s.tool.rotation, before.rotation);
  update_arm(a, away, false, s);  // released: nothing jumps
  EXPECT_NEAR((s.tool.translation - before.translation).norm(), 0, 1e-15);
  EXPECT_NEAR((s.tool.rotation - before.rotation).norm(), 0, 1e-15);
  Pose nudge = away;
  nudge.translation += Vec3(0, 0, 0.003);  // then moves relative to the new anchor
  update_arm(a, nudge, false, s);
  EXPECT_NEAR((s.commanded.translation - before.translation - Vec3(0, 0, 0.001)).norm(), 0, 1e-15);
}

}  // namespace
}  // namespace imasim::surgery
