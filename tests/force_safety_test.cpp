// The safety filter: whatever the force model asks, the command stays finite, within the device's
// limit and its rate limit, ramps in, fades when the model is stale, and is zero for a lost device.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "haptics/force_safety.hpp"

namespace imasim::haptics {
namespace {

constexpr double kTick = 1e-3;

SafetyParams no_ramp() {
  SafetyParams p;
  p.ramp_s = 0;
  return p;
}

TEST(ForceSafety, RampsInOverItsTimeAfterStartAndAfterTheClutch) {
  SafetyParams p;
  p.max_rate = 1e9;  // the ramp alone
  ForceSafety s(p, 0.0);
  const Vec3 f(0, 0, 2);
  EXPECT_NEAR(s.filter(f, 0.125, 0, true).z(), 0.5, 1e-12);  // a quarter of 0.5 s
  EXPECT_NEAR(s.filter(f, 0.5, 0, true).z(), 2.0, 1e-12);
  s.restart_ramp(1.0);
  EXPECT_NEAR(s.filter(f, 1.25, 0, true).z(), 1.0, 1e-12);
}

TEST(ForceSafety, ClampsToTheDeviceAndLimitsTheRate) {
  ForceSafety s(no_ramp(), 0.0);
  // 10 N asked of a 3.3 N device, in one tick from zero: 0.5 N (500 N/s x 1 ms).
  Vec3 f = s.filter(Vec3(10, 0, 0), kTick, 0, true);
  EXPECT_NEAR(f.x(), 0.5, 1e-12);
  double t = kTick;
  for (int k = 0; k < 20; ++k)
    f = s.filter(Vec3(10, 0, 0), t += kTick, 0, true);
  EXPECT_NEAR(f.x(), 3.3, 1e-12);
  EXPECT_GT(s.counters().clamped, 0u);
  EXPECT_GT(s.counters().rate_limited, 0u);
}

TEST(ForceSafety, TheWatchdogFadesAStaleModelToZero) {
  SafetyParams p = no_ramp();
  p.max_rate = 1e9;
  ForceSafety s(p, 0.0);
  const Vec3 f(0, 2, 0);
  EXPECT_NEAR(s.filter(f, 0.001, 0.019, true).y(), 2.0, 1e-12);  // 19 ms old: fresh
  EXPECT_NEAR(s.filter(f, 0.002, 0.025, true).y(), 1.0, 1e-12);  // half way through the fade
  EXPECT_LT(s.filter(f, 0.003, 0.030, true).norm(), 1e-12);      // the end of the fade
  EXPECT_EQ(s.filter(f, 0.004, 0.031, true), Vec3::Zero());      // faded out
  EXPECT_EQ(s.filter(f, 0.005, NAN, true), Vec3::Zero());        // an unknown age is stale
  EXPECT_EQ(s.counters().stale_model, 4u);
}

TEST(ForceSafety, ALostDeviceGetsZeroAtOnce) {
  ForceSafety s(no_ramp(), 0.0);
  double t = 0;
  for (int k = 0; k < 20; ++k)
    s.filter(Vec3(0, 0, 3), t += kTick, 0, true);
  ASSERT_NEAR(s.last_command().z(), 3.0, 1e-12);
  // The very next tick after the device is lost: zero, not a rate-limited decline.
  EXPECT_EQ(s.filter(Vec3(0, 0, 3), t += kTick, 0, false), Vec3::Zero());
  EXPECT_EQ(s.counters().device_lost, 1u);
}

TEST(ForceSafety, GarbageInNeverReachesTheDeviceOutOfBounds) {
  // NaN, infinities, huge values, negative and NaN times: every command finite, within the
  // device's limit, and within the rate limit of the previous command.
  const SafetyParams p;
  ForceSafety s(p, 0.0);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1e6, 1e6);
  const double inf = std::numeric_limits<double>::infinity();
  Vec3 previous = Vec3::Zero();
  double t = 0;
  for (int k = 0; k < 20000; ++k) {
    Vec3 f(u(rng), u(rng), u(rng));
    if (k % 7 == 0) f.x() = NAN;
    if (k % 11 == 0) f.y() = inf;
    if (k % 13 == 0) f *= 1e-6;
    const double age = k % 17 == 0 ? NAN : (k % 5) * 0.006;
    t += kTick;
    const Vec3 out = s.filter(f, t, age, k % 101 != 0);
    ASSERT_TRUE(out.allFinite()) << k;
    ASSERT_LE(out.norm(), p.device_max_force + 1e-12) << k;
    if (k % 101 != 0) {
      ASSERT_LE((out - previous).norm(), p.max_rate * kTick + 1e-9) << k;
    }
    previous = out;
  }
  EXPECT_GT(s.counters().non_finite, 0u);
}

}  // namespace
}  // namespace imasim::haptics
