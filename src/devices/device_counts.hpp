#pragma once
// What a device has refused and whom it has served, as a plain value (no allocation, trivially
// copyable) that the 1 kHz loop can hand to the window: the panel shows it by reason and by
// device name (nothing is refused in silence). Reasons are OpenIGTLink's (IgtlRefusal),
// the only devices that refuse messages today.
#include <array>
#include <cstdint>

#include "devices/igtl_codec.hpp"

namespace imasim::devices {

struct DeviceCounts {
  std::array<std::uint64_t, kIgtlRefusals> refused_by_reason{};
  // By the sender's device name, in the order first refused.
  std::array<IgtlNameRefusals, kIgtlRefusedNames> refused_names{};
  std::size_t named = 0;
  std::uint64_t refused_others = 0;  // names past the table's room
  std::uint64_t peers_seen = 0, peers_dropped = 0, peers_connected = 0, peers_turned_away = 0;

  std::uint64_t refused_total() const;
  // Adds a protocol's counters (names already counted add up).
  void add(const IgtlCounters& c);
};

}  // namespace imasim::devices
