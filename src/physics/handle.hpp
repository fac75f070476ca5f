#pragma once
// A handle to a constraint: slot index + generation. Safe to keep across threads and across
// removals: a handle whose constraint was removed no longer resolves (its generation is stale).
#include <cstdint>

namespace imasim::physics {

inline constexpr std::uint32_t kInvalidIndex = 0xffffffffu;

template <class Row>
struct Handle {
  std::uint32_t index = kInvalidIndex;
  std::uint32_t generation = 0;

  bool is_null() const { return index == kInvalidIndex; }
  friend bool operator==(const Handle&, const Handle&) = default;
};

}  // namespace imasim::physics
