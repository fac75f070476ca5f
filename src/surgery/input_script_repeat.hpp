#pragma once
// An input script played several times in a row (`imasim run --repeat N`, the soak run): a
// practice cycle that starts and ends at the same pose becomes a session of any length. Each
// copy starts `period` seconds after the previous one; between copies the poses move from one
// copy's last key to the next copy's first, as between any two keys.
#include <cstdint>

#include "surgery/input_script.hpp"

namespace imasim::surgery {

// The copies' keys, in time order. Throws InputScriptError when `times` is 0 or `period` is
// shorter than the script (its copies would overlap) or not finite.
InputScript repeat_input_script(const InputScript& script, std::uint32_t times, double period);

}  // namespace imasim::surgery
