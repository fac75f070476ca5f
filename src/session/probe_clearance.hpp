#pragma once
// What the last search of the heart at each of an instrument's probe points (surface_stops.hpp)
// proved: the point `from` was outside every component of the heart (each found within the
// search), `distance` from the nearest, while the heart had
// travelled `travel_at`. No point of the heart's surface moves farther than the heart's travel
// (tissue/heart_clearance.hpp), so after the probe moves s and the heart travels t more, the
// surface is no nearer than distance - s - t. The stops' checks skip a search whose answer that
// bound already gives, and answer as if they had searched.
#include <array>
#include <cstdint>

#include "math/types.hpp"
#include "tissue/heart_field.hpp"

namespace imasim::session {

struct ProbeClearance {
  std::array<Real, 3> distance{Real(-1), Real(-1), Real(-1)};  // < 0: nothing known (unit: m)
  std::array<Vec3, 3> from{Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
  std::array<Real, 3> travel_at{};          // (unit: m)
  std::uint64_t searched = 0, skipped = 0;  // the checks searched, and answered by the bound
};

// Whether probe point k (< 3), now at x, is nearer the heart than `clearance` or inside it: the
// answer of heart_signed_distance(heart, x, search) < clearance, from the bound when it proves
// the point clear, else searched (and what the search proves kept).
bool nearer_the_heart_than(tissue::HeartField& heart, ProbeClearance& known, std::size_t k,
                           const Vec3& x, Real clearance, Real search);

}  // namespace imasim::session
