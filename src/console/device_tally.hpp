#pragma once
// What the live console tells the window about its devices while it runs (nothing is
// refused in silence): a plain value the 1 kHz loop publishes without allocating.
#include <array>
#include <cstdint>

#include "console/loss_guard.hpp"
#include "devices/device_counts.hpp"

namespace imasim::console {

// The devices' refusals and peers and the parts' losses as the loop last published them (every
// kTallyTicks ticks): what the window's panel shows while the session runs.
struct DeviceTally {
  devices::DeviceCounts counts;
  std::array<PartLoss, kParts> losses{};  // left hand, right hand, pedal
  double time_s = -1;                     // console clock when published; < 0: never
};
inline constexpr std::uint64_t kTallyTicks = 16;

}  // namespace imasim::console
