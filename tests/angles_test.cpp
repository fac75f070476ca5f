#include <gtest/gtest.h>

#include "math/angles.hpp"

namespace imasim {
namespace {

TEST(WrapAngle, KeepsAnglesInsideTheRange) {
  EXPECT_DOUBLE_EQ(wrap_angle(0.5), 0.5);
  EXPECT_DOUBLE_EQ(wrap_angle(-0.5), -0.5);
  EXPECT_DOUBLE_EQ(wrap_angle(kPi), kPi);
}

TEST(WrapAngle, TakesTheShortWayRound) {
  // 179 deg minus -179 deg is 2 deg the short way.
  EXPECT_NEAR(wrap_angle(degrees_to_radians(179) - degrees_to_radians(-179)),
              degrees_to_radians(-2), 1e-12);
  EXPECT_NEAR(wrap_angle(3 * kPi / 2), -kPi / 2, 1e-12);
  EXPECT_NEAR(wrap_angle(-3 * kPi / 2), kPi / 2, 1e-12);
  EXPECT_NEAR(wrap_angle(-kPi), kPi, 1e-12);  // the range is (-pi, pi]
  EXPECT_NEAR(wrap_angle(20 * kPi + 0.25), 0.25, 1e-12);
}

}  // namespace
}  // namespace imasim
