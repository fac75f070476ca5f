#include <gtest/gtest.h>

#include "precision.hpp"

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
  // Rounding is that of Real at the magnitude of the input angle.
  using test::ulps;
  EXPECT_NEAR(wrap_angle(degrees_to_radians(179) - degrees_to_radians(-179)),
              degrees_to_radians(-2), ulps(2, 2 * kPi));
  EXPECT_NEAR(wrap_angle(3 * kPi / 2), -kPi / 2, ulps(2, 2 * kPi));
  EXPECT_NEAR(wrap_angle(-3 * kPi / 2), kPi / 2, ulps(2, 2 * kPi));
  EXPECT_NEAR(wrap_angle(-kPi), kPi, ulps(2, kPi));  // the range is (-pi, pi]
  EXPECT_NEAR(wrap_angle(20 * kPi + 0.25), 0.25, ulps(2, 21 * kPi));
}

}  // namespace
}  // namespace imasim
