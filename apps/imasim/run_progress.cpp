#include "run_progress.hpp"

#include <unistd.h>

#include <cstdio>
#include <ostream>
#include <string>

namespace imasim::cli {
namespace {

std::string remaining_text(double seconds) {
  char text[48];
  if (seconds < 120) {
    std::snprintf(text, sizeof text, "%.0f s", seconds);
  } else if (seconds < 7200) {
    std::snprintf(text, sizeof text, "%.0f min", seconds / 60);
  } else {
    std::snprintf(text, sizeof text, "%.1f h", seconds / 3600);
  }
  return text;
}

}  // namespace

RunProgress::RunProgress(const char* who, double total_s, double dt, bool show_progress,
                         std::ostream& out)
    : who_(who),
      total_s_(total_s),
      dt_(dt),
      show_(show_progress || ::isatty(STDERR_FILENO)),
      terminal_(::isatty(STDERR_FILENO)),
      out_(out),
      start_(Clock::now()),
      last_report_(start_) {}

void RunProgress::update(double simulated_s) {
  const Clock::time_point now = Clock::now();
  const double wall = std::chrono::duration<double>(now - start_).count();
  if (!warned_ && now - start_ >= kSpeedJudgedAfter && simulated_s > 0) {
    warned_ = true;
    const double slowdown = wall / simulated_s;
    const double left = (total_s_ - simulated_s) * slowdown;
    if (slowdown > 1 && left > 10) {
      char text[200];
      std::snprintf(text, sizeof text,
                    "%s: %.1fx slower than real time on this machine (%.1f ms a %.0f ms "
                    "step); the %.1f s asked for will take about %s more",
                    who_, slowdown, 1e3 * dt_ * slowdown, 1e3 * dt_, total_s_,
                    remaining_text(left).c_str());
      out_ << (line_open_ ? "\n" : "") << text << '\n';
      line_open_ = false;
    }
  }
  if (!show_ || now - last_report_ < kProgressInterval) return;
  last_report_ = now;
  char text[160];
  std::snprintf(text, sizeof text, "%s: %.1f of %.1f s simulated (%.0f %%), %.2fx real time", who_,
                simulated_s, total_s_, total_s_ > 0 ? 100 * simulated_s / total_s_ : 100.0,
                wall > 0 ? simulated_s / wall : 0.0);
  if (terminal_) {
    out_ << '\r' << text << std::flush;
    line_open_ = true;
  } else {
    out_ << text << '\n';
  }
}

void RunProgress::finish() {
  if (line_open_) out_ << '\n';
  line_open_ = false;
}

}  // namespace imasim::cli
