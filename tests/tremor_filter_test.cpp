// Tremor filtering (devices/tremor_filter.hpp): a second-order Butterworth low-pass whose
// measured response matches its closed form, passes deliberate motion, removes most of a
// physiological tremor and keeps a held hand exactly still.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "devices/tremor_filter.hpp"

namespace imasim::devices {
namespace {

// Amplitude of the filter's steady response to a unit sine at `f` (Hz), sampled at 1 kHz.
Real measured_gain(Real f) {
  TremorFilter filter;
  Real peak = 0;
  const int n = 6000;
  for (int k = 0; k < n; ++k) {
    const Real t = Real(k) * Real(1e-3);
    const Real y = filter.filter(Vec3(std::sin(2 * std::numbers::pi_v<Real> * f * t), 0, 0)).x();
    if (k > n / 2) peak = std::max(peak, std::abs(y));
  }
  return peak;
}

Real shake_filtered(TremorFilter& f, Real x) {
  return f.filter(Vec3(x, 0, 0)).x();
}

TEST(TremorFilter, ResponseMatchesTheButterworthClosedForm) {
  const TremorFilter filter;
  for (const Real f : {0.5, 1.0, 2.0, 6.0, 10.0, 20.0}) {
    // The analog prototype |H| = 1 / sqrt(1 + (f / fc)^4); the bilinear transform pre-warped at
    // the cutoff matches it exactly there and closely below 20 Hz at 1 kHz.
    const Real analog = 1 / std::sqrt(1 + std::pow(f / 6, 4));
    EXPECT_NEAR(filter.gain_at(f), analog, 0.01 * analog + 1e-4) << f;
    EXPECT_NEAR(measured_gain(f), filter.gain_at(f), 0.01) << f;
  }
  EXPECT_NEAR(filter.gain_at(6), std::sqrt(0.5), 1e-9);  // -3 dB at the cutoff
}

TEST(TremorFilter, PassesDeliberateMotionAndRemovesTremor) {
  // A 20 mm reach at 0.5 Hz, with and without a 0.5 mm tremor at 10 Hz on top: the filter is
  // linear, so the difference of the two outputs is the tremor that gets through.
  TremorFilter steady, shaky;
  Real passed = 0, reach_gain = 0;
  for (int k = 0; k < 4000; ++k) {
    const Real t = Real(k) * Real(1e-3);
    const Real reach = Real(0.01) * (1 - std::cos(std::numbers::pi_v<Real> * t));
    const Real shake = Real(0.0005) * std::sin(2 * std::numbers::pi_v<Real> * 10 * t);
    const Real a = steady.filter(Vec3(reach, 0, 0)).x();
    const Real b = shake_filtered(shaky, reach + shake);
    if (k > 2000) passed = std::max(passed, std::abs(b - a));
    reach_gain = std::max(reach_gain, a);
  }
  // At 10 Hz the gain is 0.34: 0.17 mm of the 0.5 mm get through; the reach keeps its 20 mm.
  EXPECT_NEAR(passed, 0.0005 * TremorFilter().gain_at(10), 0.00002);
  EXPECT_NEAR(reach_gain, 0.02, 0.0002);
}

TEST(TremorFilter, AHeldHandStaysExactlyStillAndOffPassesThrough) {
  TremorFilter filter;
  const Vec3 held(0.01, -0.02, 0.03);
  for (int k = 0; k < 1000; ++k)
    EXPECT_EQ(filter.filter(held), held);
  TremorFilter off({0, 1000});
  EXPECT_EQ(off.filter(Vec3(1, 2, 3)), Vec3(1, 2, 3));
  EXPECT_EQ(off.gain_at(50), 1);
  // A non-finite sample restarts the filter instead of poisoning it.
  TremorFilter f2;
  f2.filter(held);
  f2.filter(Vec3(NAN, 0, 0));
  EXPECT_TRUE(f2.filter(held).allFinite());
}

}  // namespace
}  // namespace imasim::devices
