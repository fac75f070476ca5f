#pragma once
// The 1 kHz haptic loop on its own thread (SPEC S5): a steady clock and a deadline
// schedule, sleeping until shortly before each deadline and spinning the last part (a sleep
// alone wakes up to tens of microseconds late). Each tick calls the caller's function (read the
// device, evaluate the local model, command the force) and records the period between tick
// starts and the tick's own duration (the latency from pose read to force command).
// A tick that starts more than half a period after its deadline is a missed deadline; when the
// loop falls more than a period behind it starts a fresh schedule instead of running the missed
// ticks back to back.
#include <atomic>
#include <cstdint>
#include <functional>
#include <thread>

#include "haptics/duration_histogram.hpp"

namespace imasim::haptics {

struct HapticLoopConfig {
  double rate_hz = 1000;
  double spin_s = 150e-6;  // the last part of each wait, spent spinning (unit: s)
  // SCHED_FIFO priority asked for the loop's thread (0: none). Given where the process may
  // (root, CAP_SYS_NICE or an rtprio limit), so that the physics thread cannot preempt a tick;
  // elsewhere the loop runs at normal priority and its stats say so.
  int realtime_priority = 80;
};

struct HapticLoopStats {
  std::uint64_t ticks = 0;
  std::uint64_t missed_deadlines = 0;
  double rate_hz = 0;  // ticks over the loop's running time
  double period_mean_us = 0, period_p50_us = 0, period_p99_us = 0, period_p999_us = 0,
         period_max_us = 0;
  double period_p99_error_us = 0;  // p99 of |period - nominal|
  double latency_p50_us = 0, latency_p99_us = 0, latency_max_us = 0;
  bool realtime = false;  // the thread ran with the real-time priority asked for
};

class HapticLoop {
 public:
  // `tick(now_s)`: now_s on the steady clock, in seconds since the loop started.
  HapticLoop(const HapticLoopConfig& config, std::function<void(double now_s)> tick);
  ~HapticLoop();
  HapticLoop(const HapticLoop&) = delete;
  HapticLoop& operator=(const HapticLoop&) = delete;

  // Called on the loop's own thread as it ends (before start): what the tick's callees keep per
  // thread there (a library's thread-local state) is freed on the thread that owns it.
  void at_thread_exit(std::function<void()> done) { at_exit_ = std::move(done); }

  void start();
  void stop();  // joins the thread; safe to call twice
  bool running() const { return running_.load(); }
  // Ticks so far (any thread, while running).
  std::uint64_t ticks() const { return ticks_.load(std::memory_order_relaxed); }
  // The figures of the run; after stop() (the loop thread owns them while it runs, so that it
  // never waits on a reader). Empty while running.
  HapticLoopStats stats() const;

 private:
  void run();

  HapticLoopConfig config_;
  std::function<void(double)> tick_;
  std::function<void()> at_exit_;
  std::atomic<bool> stop_{false}, running_{false};
  std::thread thread_;
  DurationHistogram period_, period_error_, latency_;
  std::atomic<std::uint64_t> ticks_{0};
  std::uint64_t missed_ = 0;
  bool realtime_ = false;
  double elapsed_s_ = 0;
};

}  // namespace imasim::haptics
