// The 4D heart (SPEC S3): periodic, C1, physiological volume curve, static mode.
#include <gtest/gtest.h>

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
  // The analytic curve itself: 1 at end-diastole, 1 - EF at end-systole, C1 at both.
  EXPECT_DOUBLE_EQ(heart_volume_fraction(p, 0), 1.0);
  EXPECT_NEAR(heart_volume_fraction(p, p.systole_fraction), 1 - p.ejection_fraction, 1e-15);
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
