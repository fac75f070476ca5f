#include "autopilot/tremor.hpp"

#include <cmath>
#include <numbers>

#include "tissue/random.hpp"

namespace imasim::autopilot {

Tremor::Tremor(std::uint64_t seed, Real rms) {
  tissue::SplitMix64 random(seed);
  for (auto& axis : waves_) {
    for (Wave& w : axis) {
      w.omega = 2 * std::numbers::pi * (8 + 4 * double(random.uniform()));  // 8-12 Hz
      w.phase = 2 * std::numbers::pi * double(random.uniform());
    }
  }
  // Independent sinusoids of amplitude a have RMS a sqrt(n / 2) together.
  amplitude_ = double(rms) / std::sqrt(kWaves / 2.0);
}

Vec3 Tremor::at(double t) const {
  Vec3 out = Vec3::Zero();
  for (int axis = 0; axis < 3; ++axis) {
    double sum = 0;
    for (const Wave& w : waves_[std::size_t(axis)])
      sum += std::sin(w.omega * t + w.phase);
    out[axis] = Real(amplitude_ * sum);
  }
  return out;
}

}  // namespace imasim::autopilot
