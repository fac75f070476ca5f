#pragma once
// What a long headless run says while it runs, on stderr: once, early, that it is slower than
// real time and how long it will take (instead of appearing to hang); then, when asked or when
// stderr is a terminal, the simulated time done every few seconds.
#include <chrono>
#include <iosfwd>

namespace imasim::cli {

class RunProgress {
 public:
  // `total_s`: the simulated time asked for (unit: s); `dt`: one step (unit: s); `who` starts
  // each line ("imasim run").
  RunProgress(const char* who, double total_s, double dt, bool show_progress, std::ostream& out);
  // After each step, with the simulated time reached (unit: s).
  void update(double simulated_s);
  // Ends a progress line left open on a terminal.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  const char* who_;
  double total_s_, dt_;
  bool show_, terminal_, warned_ = false, line_open_ = false;
  std::ostream& out_;
  Clock::time_point start_, last_report_;
};

// Wall-clock time before the speed is judged, and between progress lines.
inline constexpr std::chrono::seconds kSpeedJudgedAfter{2}, kProgressInterval{5};

}  // namespace imasim::cli
