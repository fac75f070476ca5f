#pragma once
// Tolerances for checks on solver results: a few units of rounding of the solver's scalar
// (Real, float by default) at the scale of the quantity checked.
#include <limits>

#include "math/types.hpp"

namespace imasim::test {

inline constexpr double kEps = std::numeric_limits<Real>::epsilon();

// n units of rounding at magnitude `scale`.
inline constexpr double ulps(double n, double scale) {
  return n * kEps * scale;
}

}  // namespace imasim::test
