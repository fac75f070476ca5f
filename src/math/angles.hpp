#pragma once
// Angle helpers (unit: rad).
#include <cmath>
#include <numbers>

#include "math/types.hpp"

namespace imasim {

inline constexpr Real kPi = std::numbers::pi_v<Real>;

// Maps any finite angle to (-pi, pi]; used so that a constraint on an angle near +-pi sees the
// short way round (179 deg vs -179 deg is 2 deg apart, not 358 deg).
inline Real wrap_angle(Real a) {
  if (a > kPi || a <= -kPi) {
    a = std::remainder(a, 2 * kPi);
    if (a <= -kPi) a += 2 * kPi;
  }
  return a;
}

inline constexpr Real degrees_to_radians(Real deg) {
  return deg * kPi / Real(180);
}

}  // namespace imasim
