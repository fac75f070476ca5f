#include "haptics/force_safety.hpp"

#include <algorithm>
#include <cmath>

namespace imasim::haptics {

ForceSafety::ForceSafety(const SafetyParams& params, double start_s)
    : params_(params), ramp_start_s_(start_s), last_s_(start_s) {}

void ForceSafety::restart_ramp(double now_s) {
  ramp_start_s_ = now_s;
}

Vec3 ForceSafety::filter(const Vec3& requested, double now_s, double model_age_s, bool device_ok) {
  const double dt = std::max(0.0, now_s - last_s_);
  last_s_ = now_s;
  if (!device_ok) {
    ++counters_.device_lost;
    last_ = Vec3::Zero();
    return last_;
  }
  Vec3 f = requested;
  if (!f.allFinite()) {
    ++counters_.non_finite;
    f.setZero();
  }
  const Real magnitude = f.norm();
  if (magnitude > params_.device_max_force) {
    ++counters_.clamped;
    f *= params_.device_max_force / magnitude;
  }
  const double ramp =
      params_.ramp_s > 0 ? std::clamp((now_s - ramp_start_s_) / params_.ramp_s, 0.0, 1.0) : 1.0;
  double fade = 1.0;
  if (!(model_age_s <= params_.stale_after_s)) {  // NaN ages count as stale
    ++counters_.stale_model;
    const double over = model_age_s - params_.stale_after_s;
    fade = params_.fade_s > 0 && std::isfinite(over)
               ? std::clamp(1.0 - over / params_.fade_s, 0.0, 1.0)
               : 0.0;
  }
  f *= Real(ramp * fade);
  // Rate limit: |f - last| <= max_rate dt.
  const Vec3 change = f - last_;
  const Real allowed = params_.max_rate * Real(dt);
  if (change.norm() > allowed) {
    ++counters_.rate_limited;
    f = last_ + change * (allowed / change.norm());
  }
  last_ = f;
  return f;
}

}  // namespace imasim::haptics
