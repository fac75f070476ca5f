#include "session/probe_clearance.hpp"

#include <cmath>

namespace imasim::session {

namespace {

// A bound must clear the clearance by this too: far above the rounding of the distances it is
// made of, far below any distance that matters (unit: m).
constexpr Real kProvenMargin = Real(1e-9);

}  // namespace

bool nearer_the_heart_than(tissue::HeartField& heart, ProbeClearance& known, std::size_t k,
                           const Vec3& x, Real clearance, Real search) {
  const Real travel = heart.clearance.travel;
  if (known.distance[k] >= 0 &&
      known.distance[k] - (x - known.from[k]).norm() - (travel - known.travel_at[k]) >
          clearance + kProvenMargin) {
    ++known.skipped;
    return false;
  }
  ++known.searched;
  const Real d = tissue::heart_signed_distance(heart, x, search);
  // Kept only when the search found every component of the heart and the point outside each:
  // d is then no more than its distance to any of them. A component not found within the search
  // may hold the point deep inside it, and be found so once its surface comes within the search.
  bool proven = true;
  for (const tissue::HeartField::Nearest& n : heart.nearest)
    proven = proven && n.triangle != tissue::HeartField::kNone && n.signed_distance >= 0;
  known.distance[k] = proven ? d : Real(-1);
  known.from[k] = x;
  known.travel_at[k] = travel;
  return d < clearance;
}

}  // namespace imasim::session
