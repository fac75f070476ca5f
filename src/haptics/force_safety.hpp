#pragma once
// What stands between the force model and a device's motors: every force
// commanded passes through one ForceSafety per device, in this order:
//   1. a non-finite request becomes zero (and is counted);
//   2. the magnitude is clamped to the device's maximum force;
//   3. ramp-in: scaled from 0 to 1 over `ramp_s` after start and after each clutch release;
//   4. watchdog: when the local model is older than `stale_after_s` (20 ms: four physics steps
//      missed), the force fades linearly to zero over `fade_s`;
//   5. the change from the last command is limited to `max_rate` (so a new contact or a model
//      refresh never kicks the hand);
//   6. a lost device gets zero at once (no rate limit on the way down to a device that is gone).
#include <cstdint>

#include "math/types.hpp"

namespace imasim::haptics {

struct SafetyParams {
  Real device_max_force = Real(3.3);  // (unit: N) a desktop haptic device's peak force
  Real max_rate = 500;                // (unit: N/s) 0.5 N per 1 ms tick
  double ramp_s = 0.5;                // (unit: s)
  double stale_after_s = 0.020;       // (unit: s)
  double fade_s = 0.010;              // (unit: s)
};

struct SafetyCounters {
  std::uint64_t non_finite = 0;    // requests that were NaN or infinite
  std::uint64_t clamped = 0;       // requests above the device's maximum
  std::uint64_t rate_limited = 0;  // commands held back by the rate limit
  std::uint64_t stale_model = 0;   // commands made while the local model was stale
  std::uint64_t device_lost = 0;   // commands zeroed because the device was gone
};

class ForceSafety {
 public:
  explicit ForceSafety(const SafetyParams& params, double start_s);

  // The command for time `now_s`, given the model's age and whether the device answers.
  Vec3 filter(const Vec3& requested, double now_s, double model_age_s, bool device_ok);

  // Starts the ramp again (the clutch was released: the hand and the tool meet again).
  void restart_ramp(double now_s);

  const SafetyCounters& counters() const { return counters_; }
  const Vec3& last_command() const { return last_; }

 private:
  SafetyParams params_;
  double ramp_start_s_;
  double last_s_;
  Vec3 last_ = Vec3::Zero();
  SafetyCounters counters_;
};

}  // namespace imasim::haptics
