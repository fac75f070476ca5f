// The 1 kHz loop's bookkeeping: it ticks on its own thread with increasing times, stops when
// asked, and its figures agree with each other (the rates themselves are measured by the
// benchmark, not here).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "haptics/duration_histogram.hpp"
#include "haptics/haptic_loop.hpp"

namespace imasim::haptics {
namespace {

TEST(DurationHistogram, QuantilesToTheMicrosecond) {
  DurationHistogram h(0.01);
  EXPECT_EQ(h.quantile_s(0.5), 0);
  for (int us = 1; us <= 100; ++us)
    h.add(us * 1e-6 - 0.5e-6);  // 0.5, 1.5, ... 99.5 us
  EXPECT_EQ(h.count(), 100u);
  EXPECT_NEAR(h.quantile_s(0.5), 50e-6, 1e-12);
  EXPECT_NEAR(h.quantile_s(0.99), 99e-6, 1e-12);
  EXPECT_NEAR(h.quantile_s(1.0), 100e-6, 1e-12);
  EXPECT_NEAR(h.max_s(), 99.5e-6, 1e-12);
  EXPECT_NEAR(h.mean_s(), 50e-6, 1e-12);
  h.add(1.0);  // beyond the bound: counted at it
  h.add(NAN);  // counted as zero
  EXPECT_NEAR(h.quantile_s(1.0), 0.010001, 1e-9);
}

TEST(HapticLoop, TicksOnItsOwnThreadUntilStopped) {
  std::atomic<int> calls{0};
  std::atomic<double> last_now{-1};
  std::atomic<bool> increasing{true};
  const std::thread::id test_thread = std::this_thread::get_id();
  std::atomic<bool> other_thread{true};
  HapticLoop loop(HapticLoopConfig{}, [&](double now) {
    if (now <= last_now.load()) increasing = false;
    last_now = now;
    if (std::this_thread::get_id() == test_thread) other_thread = false;
    ++calls;
  });
  loop.start();
  while (loop.ticks() < 50)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_TRUE(loop.running());
  EXPECT_EQ(loop.stats().ticks, 0u);  // figures only after stop
  loop.stop();
  loop.stop();  // twice is harmless
  const HapticLoopStats s = loop.stats();
  EXPECT_EQ(s.ticks, std::uint64_t(calls.load()));
  EXPECT_GE(s.ticks, 50u);
  EXPECT_TRUE(increasing.load());
  EXPECT_TRUE(other_thread.load());
  EXPECT_LE(s.period_p50_us, s.period_p99_us);
  EXPECT_LE(s.period_p99_us, s.period_p999_us);
  EXPECT_LE(s.period_p999_us, s.period_max_us + 1);  // quantiles to the bin's upper edge
  EXPECT_GT(s.period_mean_us, 0);
  EXPECT_GT(s.rate_hz, 0);
  EXPECT_LE(s.latency_p50_us, s.latency_p99_us);
  const int after = calls.load();
  std::this_thread::sleep_for(std::chrono::milliseconds(5));
  EXPECT_EQ(calls.load(), after);  // stopped means stopped
}

}  // namespace
}  // namespace imasim::haptics
