#pragma once
// Tremor filtering of a hand's position, as robotic consoles do: a second-order
// Butterworth low-pass per axis at `cutoff_hz` (6 Hz by default: physiological tremor lies at
// 8-12 Hz, deliberate surgical motion below 2 Hz), sampled at the loop's rate, designed by the
// bilinear transform with the cutoff pre-warped. Unit gain at rest, so a held hand stays put.
#include "math/types.hpp"

namespace imasim::devices {

struct TremorFilterParams {
  Real cutoff_hz = 6;     // (unit: Hz); 0 turns the filter off
  Real sample_hz = 1000;  // the rate filter() is called at (unit: Hz)
};

class TremorFilter {
 public:
  explicit TremorFilter(const TremorFilterParams& params = {});
  // The filtered position for the next sample; the first sample starts the filter at rest there.
  Vec3 filter(const Vec3& x);
  void reset() { started_ = false; }
  // The filter's gain at a frequency (closed form of the digital filter; for tests and docs).
  Real gain_at(Real frequency_hz) const;

 private:
  bool enabled_ = false, started_ = false;
  Real b0_ = 1, b1_ = 0, b2_ = 0, a1_ = 0, a2_ = 0, sample_hz_ = 1000;
  Vec3 origin_ = Vec3::Zero(), x1_ = Vec3::Zero(), x2_ = Vec3::Zero(), y1_ = Vec3::Zero(),
       y2_ = Vec3::Zero();
};

}  // namespace imasim::devices
