#pragma once
// Levenshtein distance between two names, for "did you mean" suggestions in error messages.
#include <cstddef>
#include <string_view>

namespace imasim {

std::size_t edit_distance(std::string_view a, std::string_view b);

}  // namespace imasim
