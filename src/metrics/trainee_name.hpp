#pragma once
// A trainee's name as the records keep it: what a person types at a console and an educator
// reads back in a table, so text only (UTF-8, no control characters, no surrounding spaces)
// and short.
#include <cstddef>
#include <string>
#include <string_view>

namespace imasim::metrics {

// At most this many characters (Unicode code points).
inline constexpr std::size_t kMaxTraineeNameCharacters = 64;

// Empty when `name` is acceptable, else why not ("is empty", "has 70 characters, above the
// limit of 64", "has a control character at byte 3", ...).
std::string trainee_name_problem(std::string_view name);

}  // namespace imasim::metrics
