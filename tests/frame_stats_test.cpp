// Frame-rate figures (ui/frame_stats.hpp): median frame rate and p99 frame time by nearest rank.
#include <gtest/gtest.h>

#include <cmath>

#include "ui/frame_stats.hpp"

namespace imasim::ui {
namespace {

TEST(FrameStats, MedianRateAndP99Time) {
  std::vector<double> p(99, 0.02);  // 50 fps
  p.push_back(0.5);                 // one stall
  const FrameStats s = frame_stats(p);
  EXPECT_DOUBLE_EQ(s.median_fps, 50);
  EXPECT_DOUBLE_EQ(s.p99_frame_ms, 20);  // the 99th of 100
  p.push_back(0.5);
  EXPECT_DOUBLE_EQ(frame_stats(p).p99_frame_ms, 500);
  EXPECT_NEAR(frame_stats({0.01, 0.03}).mean_fps, 50, 1e-9);
  EXPECT_EQ(frame_stats({}).median_fps, 0);
  EXPECT_EQ(frame_stats({0.0, -1.0, NAN}).median_fps, 0);
}

}  // namespace
}  // namespace imasim::ui
