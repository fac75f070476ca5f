#pragma once
// Wall-clock lap timing for the step's profile (MuJoCo's mjtTimer, Box2D's b2Profile). Reading
// the clock never changes a result: profiles are reports, not state, and are left out of hashes.
#include <chrono>

namespace imasim {

class Stopwatch {
 public:
  Stopwatch() : last_(Clock::now()) {}

  // Seconds since construction or the previous lap (unit: s).
  double lap() {
    const Clock::time_point now = Clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return seconds;
  }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point last_;
};

}  // namespace imasim
