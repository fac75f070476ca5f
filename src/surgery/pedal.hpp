#pragma once
// The electrocautery foot pedal (SPEC S4): off, or the current's mode while pressed.
#include <cstdint>

namespace imasim::surgery {

enum class PedalMode : std::uint8_t { off, cut, coag };

const char* to_string(PedalMode mode);

}  // namespace imasim::surgery
