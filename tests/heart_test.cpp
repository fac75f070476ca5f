// The 4D heart (SPEC S3): periodic, C1, physiological volume curve (ejection, rapid filling,
// diastasis, atrial contraction; 70 % is diastasis), static mode.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tissue/heart.hpp"

namespace imasim::tissue {
namespace {

std::vector<Vec3> shape(const HeartModel& h, double t) {
  std::vector<Vec3> x;
  interpolate_heart(h, t, x);
  return x;
}

double max_difference(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    m = std::max(m, double((a[i] - b[i]).norm()));
  return m;
}

TEST(Heart, HasElevenPhasesOfOneTopologyAndTwoVentricles) {
  const HeartModel h = make_procedural_heart({});
  EXPECT_EQ(h.keyframes.size(), 11u);
  for (const auto& k : h.keyframes)
    EXPECT_EQ(k.size(), h.topology.vertices.size());
  ASSERT_EQ(h.component_start.size(), 3u);  // LV, RV, end
  EXPECT_GT(component_volume(h, h.keyframes[0], 0), 0);
  EXPECT_GT(component_volume(h, h.keyframes[0], 1), 0);
}

TEST(Heart, OneCycleLaterTheSurfaceIsTheSame) {
  const HeartModel h = make_procedural_heart({});
  for (const double t : {0.0, 0.13, 0.5, 0.71, 0.999}) {
    EXPECT_LT(max_difference(shape(h, t), shape(h, t + 1)), 1e-12) << t;
    EXPECT_LT(max_difference(shape(h, t), shape(h, t + 3)), 1e-12) << t;
  }
}

TEST(Heart, PassesThroughTheKeyframesAndIsC1AtEach) {
  const HeartModel h = make_procedural_heart({});
  const double n = 11, e = 1e-6;
  for (int k = 0; k < 11; ++k) {
    const double t = k / n;
    EXPECT_LT(max_difference(shape(h, t), h.keyframes[k]), 1e-12);
    // One-sided derivatives just left and right of the keyframe agree (C1).
    const auto left = shape(h, t - 2 * e), mid_left = shape(h, t - e), here = shape(h, t);
    const auto mid_right = shape(h, t + e), right = shape(h, t + 2 * e);
    for (std::size_t i = 0; i < here.size(); i += 37) {
      const Vec3 d_left = (3 * here[i] - 4 * mid_left[i] + left[i]) / (2 * e);
      const Vec3 d_right = (-3 * here[i] + 4 * mid_right[i] - right[i]) / (2 * e);
      EXPECT_LT((d_left - d_right).norm(), 1e-4 * (1 + d_left.norm())) << "keyframe " << k;
    }
  }
}

TEST(Heart, VolumeCurveGivesTheEjectionFractionAndSystole) {
  const HeartParams p;
  const HeartModel h = make_procedural_heart(p);
  double v_max = 0, v_min = 1e9, t_min = 0;
  for (int s = 0; s < 440; ++s) {
    const double t = s / 440.0;
    const double v = component_volume(h, shape(h, t), 0);
    if (v > v_max) v_max = v;
    if (v < v_min) v_min = v, t_min = t;
  }
  const double ef = (v_max - v_min) / v_max;
  EXPECT_GT(ef, 0.55);  // stated range: 60 % +- 5 %
  EXPECT_LT(ef, 0.65);
  EXPECT_NEAR(t_min, p.systole_fraction, 1.0 / 11);  // end-systole after about 35 % of the cycle
  // The analytic curve itself: 1 at end-diastole, 1 - EF at end-systole.
  EXPECT_DOUBLE_EQ(heart_volume_fraction(p, 0), 1.0);
  EXPECT_NEAR(heart_volume_fraction(p, p.systole_fraction), 1 - p.ejection_fraction, 1e-15);
}

// dV/dt of the analytic curve (unit: EDV per cycle), central difference.
double volume_rate(const HeartParams& p, double t) {
  const double e = 1e-6;
  return (heart_volume_fraction(p, t + e) - heart_volume_fraction(p, t - e)) / (2 * e);
}

TEST(Heart, SeventyPercentIsDiastasisTheQuietestPhase) {
  const HeartParams p;
  const CardiacPhases c = cardiac_phases(p);
  // R-R convention: 0.7 lies in diastasis, after rapid filling and before the atria contract.
  EXPECT_LT(c.end_rapid_filling, 0.7);
  EXPECT_GT(c.atrial_start, 0.7);
  double peak = 0;
  for (int k = 0; k < 20000; ++k)
    peak = std::max(peak, std::abs(volume_rate(p, k / 20000.0)));
  const double quiet = std::abs(volume_rate(p, 0.7));
  // Diastasis' slow inflow: 3 % of the stroke volume over its 0.3 of diastole.
  EXPECT_NEAR(volume_rate(p, 0.7), 0.03 * p.ejection_fraction / (0.3 * (1 - p.systole_fraction)),
              1e-8);
  EXPECT_LT(quiet, 0.1 * peak);
  // Slower than anywhere in ejection or rapid filling (away from their ends, where the rate
  // passes through zero at end-diastole and end-systole).
  auto slower_throughout = [&](double from, double to) {
    for (int k = 1; k < 100; ++k) {
      const double t = from + (to - from) * (0.1 + 0.8 * k / 100.0);
      EXPECT_GT(std::abs(volume_rate(p, t)), quiet) << "t = " << t;
    }
  };
  slower_throughout(0, c.end_systole);
  slower_throughout(c.end_systole, c.end_rapid_filling);
  // The same from the meshes the scene plays back (LV volume through the keyframes).
  const HeartModel h = make_procedural_heart(p);
  auto mesh_rate = [&](double t) {
    const double e = 1e-4;
    return (component_volume(h, shape(h, t + e), 0) - component_volume(h, shape(h, t - e), 0)) /
           (2 * e);
  };
  double mesh_peak = 0;
  for (int k = 0; k < 440; ++k)
    mesh_peak = std::max(mesh_peak, std::abs(mesh_rate(k / 440.0)));
  EXPECT_LT(std::abs(mesh_rate(0.7)), 0.1 * mesh_peak);
}

TEST(Heart, VolumeCurveFillsInThreeStagesAndIsC1) {
  for (const double systole : {0.35, 0.3, 0.5}) {
    SCOPED_TRACE(systole);
    HeartParams p;
    p.systole_fraction = systole;
    const double ef = p.ejection_fraction, s = systole, d = 1 - s;
    const CardiacPhases c = cardiac_phases(p);
    EXPECT_DOUBLE_EQ(c.end_systole, s);
    EXPECT_NEAR(c.end_rapid_filling, s + 0.4 * d, 1e-15);
    EXPECT_NEAR(c.atrial_start, s + 0.7 * d, 1e-15);
    EXPECT_NEAR(c.atrial_end, s + 0.92 * d, 1e-15);
    // Ejection to 1 - EF; rapid filling gives back 75 % of the stroke volume, diastasis 3 %, the
    // atrial contraction the last 22 %; then full until the R wave.
    EXPECT_DOUBLE_EQ(heart_volume_fraction(p, 0), 1.0);
    EXPECT_NEAR(heart_volume_fraction(p, c.end_systole), 1 - ef, 1e-15);
    EXPECT_NEAR(heart_volume_fraction(p, c.end_rapid_filling), 1 - ef + 0.75 * ef, 1e-15);
    EXPECT_NEAR(heart_volume_fraction(p, c.atrial_start), 1 - 0.22 * ef, 1e-15);
    EXPECT_NEAR(heart_volume_fraction(p, c.atrial_end), 1.0, 1e-15);
    EXPECT_DOUBLE_EQ(heart_volume_fraction(p, (c.atrial_end + 1) / 2), 1.0);
    // Falls only in ejection, never rises above end-diastole.
    double previous = heart_volume_fraction(p, 0);
    for (int k = 1; k <= 10000; ++k) {
      const double t = k / 10000.0, v = heart_volume_fraction(p, t);
      if (t <= s) {
        EXPECT_LE(v, previous + 1e-15) << t;
      } else {
        EXPECT_GE(v, previous - 1e-15) << t;
      }
      EXPECT_LE(v, 1.0) << t;
      previous = v;
    }
    // C1 at every join (and at the R wave, where the cycle wraps): one-sided second-order
    // differences agree to their truncation and rounding (e^2 times the third derivative, plus
    // eps / e: about 1e-9).
    const double e = 1e-6;
    auto V = [&](double x) { return double(heart_volume_fraction(p, x)); };
    for (const double t : {1.0, c.end_systole, c.end_rapid_filling, c.atrial_start, c.atrial_end}) {
      const double left = (3 * V(t) - 4 * V(t - e) + V(t - 2 * e)) / (2 * e);
      const double right = (-3 * V(t) + 4 * V(t + e) - V(t + 2 * e)) / (2 * e);
      EXPECT_NEAR(left, right, 1e-6) << "t = " << t;
    }
  }
}

TEST(Heart, ShortensAndTwistsInSystole) {
  const HeartParams p;
  const HeartModel h = make_procedural_heart(p);
  const auto ed = shape(h, 0), es = shape(h, p.systole_fraction);
  const std::uint32_t lv_apex = h.component_start[1] - 1, lv_base = h.component_start[0];
  const double length_ed = (ed[lv_apex] - ed[lv_base]).norm();
  const double length_es = (es[lv_apex] - es[lv_base]).norm();
  EXPECT_LT(length_es, 0.95 * length_ed);
  EXPECT_GT(length_es, 0.80 * length_ed);
}

TEST(HeartPlayback, StaticModeDoesNotMoveAndBeatingStartsThere) {
  HeartPlayback playback;
  playback.beating = false;
  for (const double t : {0.0, 0.3, 1.7, 100.0})
    EXPECT_DOUBLE_EQ(playback.phase_at(t), 0.7);
  playback.beating = true;
  playback.heart_rate_bpm = 60;
  EXPECT_NEAR(playback.phase_at(0), 0.7, 1e-15);
  EXPECT_NEAR(playback.phase_at(0.5), 0.2, 1e-12);
  EXPECT_NEAR(playback.phase_at(1.0), 0.7, 1e-12);
}

TEST(Heart, RejectsBadParameters) {
  HeartParams p;
  p.ejection_fraction = 1.2;
  EXPECT_THROW(make_procedural_heart(p), std::invalid_argument);
  p = HeartParams{};
  p.phases = 2;
  EXPECT_THROW(make_procedural_heart(p), std::invalid_argument);
}

}  // namespace
}  // namespace imasim::tissue
