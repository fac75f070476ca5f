#pragma once
// Physiological tremor (8-12 Hz) as a smooth, deterministic function of time: per axis a sum of
// three sinusoids whose frequencies and phases come from a seed, scaled to a given RMS. The same
// seed and time always give the same offset, so a trial replays bit for bit.
#include <array>
#include <cstdint>

#include "math/types.hpp"

namespace imasim::autopilot {

class Tremor {
 public:
  Tremor(std::uint64_t seed, Real rms);  // rms (unit: m)
  Vec3 at(double time_s) const;          // (unit: m)

 private:
  static constexpr int kWaves = 3;
  struct Wave {
    double omega = 0, phase = 0;  // (unit: rad/s, rad)
  };
  std::array<std::array<Wave, kWaves>, 3> waves_{};
  double amplitude_ = 0;  // of each wave (unit: m)
};

}  // namespace imasim::autopilot
