#include "haptics/haptic_loop.hpp"

#include <pthread.h>
#include <sched.h>

#include <chrono>
#include <cmath>

namespace imasim::haptics {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

}  // namespace

HapticLoop::HapticLoop(const HapticLoopConfig& config, std::function<void(double)> tick)
    : config_(config), tick_(std::move(tick)) {}

HapticLoop::~HapticLoop() {
  stop();
}

void HapticLoop::start() {
  if (running_.load()) return;
  stop_.store(false);
  running_.store(true);
  thread_ = std::thread([this] { run(); });
}

void HapticLoop::stop() {
  stop_.store(true);
  if (thread_.joinable()) thread_.join();
  running_.store(false);
}

void HapticLoop::run() {
  if (config_.realtime_priority > 0) {
    sched_param p{};
    p.sched_priority = config_.realtime_priority;
    realtime_ = pthread_setschedparam(pthread_self(), SCHED_FIFO, &p) == 0;
  }
  const auto period = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(1.0 / config_.rate_hz));
  const auto spin =
      std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(config_.spin_s));
  const double nominal_s = 1.0 / config_.rate_hz;
  const Clock::time_point start = Clock::now();
  Clock::time_point deadline = start;
  Clock::time_point previous_start{};
  bool first = true;
  while (!stop_.load(std::memory_order_relaxed)) {
    // Sleep until shortly before the deadline, then spin to it.
    if (deadline - Clock::now() > spin) std::this_thread::sleep_until(deadline - spin);
    while (Clock::now() < deadline) {
    }
    const Clock::time_point tick_start = Clock::now();
    const double late_s = seconds_between(deadline, tick_start);
    if (late_s > 0.5 * nominal_s) ++missed_;
    tick_(seconds_between(start, tick_start));
    const Clock::time_point tick_end = Clock::now();
    latency_.add(seconds_between(tick_start, tick_end));
    if (!first) {
      const double p = seconds_between(previous_start, tick_start);
      period_.add(p);
      period_error_.add(std::abs(p - nominal_s));
    }
    first = false;
    previous_start = tick_start;
    ticks_.fetch_add(1, std::memory_order_relaxed);
    deadline += period;
    // Fallen more than a period behind: the missed ticks are counted, not run back to back.
    if (tick_end - deadline > period) {
      const auto behind = (tick_end - deadline) / period;
      missed_ += std::uint64_t(behind);
      deadline += behind * period;
    }
  }
  elapsed_s_ = seconds_between(start, Clock::now());
  if (at_exit_) at_exit_();
}

HapticLoopStats HapticLoop::stats() const {
  HapticLoopStats s;
  if (running_.load()) return s;
  s.ticks = ticks_.load();
  s.missed_deadlines = missed_;
  s.rate_hz = elapsed_s_ > 0 ? double(s.ticks) / elapsed_s_ : 0;
  s.period_mean_us = period_.mean_s() * 1e6;
  s.period_p50_us = period_.quantile_s(0.5) * 1e6;
  s.period_p99_us = period_.quantile_s(0.99) * 1e6;
  s.period_p999_us = period_.quantile_s(0.999) * 1e6;
  s.period_max_us = period_.max_s() * 1e6;
  s.period_p99_error_us = period_error_.quantile_s(0.99) * 1e6;
  s.latency_p50_us = latency_.quantile_s(0.5) * 1e6;
  s.latency_p99_us = latency_.quantile_s(0.99) * 1e6;
  s.latency_max_us = latency_.max_s() * 1e6;
  s.realtime = realtime_;
  return s;
}

}  // namespace imasim::haptics
