// 3D mice (devices/spacemouse_device.hpp): the cap's push and twist move the hand as velocities
// past a dead zone; without spacenavd the device is simply not connected.
#include <gtest/gtest.h>

#include "devices/spacemouse_device.hpp"

namespace imasim::devices {
namespace {

TEST(SpaceMouse, PushAndTwistAreVelocities) {
  const SpaceMouseMapping m;
  HandInput hand;
  for (int k = 0; k < 100; ++k)  // 1 s at full push along x, half a twist about z
    apply_space_motion(m, {350, 0, 0, 0, 0, 175}, Real(0.01), hand);
  EXPECT_NEAR(hand.pose.translation.x(), m.speed, 1e-12);
  EXPECT_NEAR(hand.velocity.x(), m.speed, 1e-12);
  const Real half = (Real(0.5) - m.dead_zone) / (1 - m.dead_zone);
  const Real angle = m.turn_rate * half;
  EXPECT_TRUE(hand.pose.rotation.isApprox(axis_angle(Vec3::UnitZ(), angle), 1e-12));
  // Inside the dead zone nothing moves.
  const Pose before = hand.pose;
  apply_space_motion(m, {10, -10, 5, 3, 0, -8}, Real(1), hand);
  EXPECT_EQ(hand.pose.translation, before.translation);
  EXPECT_EQ(hand.pose.rotation, before.rotation);
}

TEST(SpaceMouse, WithoutTheDaemonItIsNotConnected) {
  SpaceMouseDevice mouse;
  ConsoleInput in;
  mouse.poll(0.0, in);
  if (mouse.connected()) GTEST_SKIP() << "a spacenavd is running here";
  EXPECT_FALSE(in.right.has_pose);
  EXPECT_EQ(mouse.info().name, "no spacenavd running");
  EXPECT_TRUE(mouse.info().drives_right);
}

}  // namespace
}  // namespace imasim::devices
