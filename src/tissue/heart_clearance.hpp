#pragma once
// What each particle's last search of the heart proved: no surface nearer than `distance` to the
// point `from` while the heart stood where it had travelled `travel_at`. The surface is the
// heart's triangles, each point of which moves no farther than the heart's farthest-moving
// vertex, so after the heart travels t more and the particle's query point moves by s, nothing
// is nearer than distance - s - t. A query whose search that bound already exceeds finds
// nothing, and is answered without searching: most of the tissue lies millimetres from the
// heart and would otherwise search it twice a step. Only a search's cost changes, never its
// answer (the scene's results are bit for bit those of searching every time).
#include <cstdint>
#include <vector>

#include "math/types.hpp"

namespace imasim::tissue {

struct HeartClearance {
  // Per particle; distance < 0: nothing known yet.
  std::vector<Real> distance;  // (unit: m)
  std::vector<Vec3> from;
  std::vector<Real> travel_at;  // (unit: m)
  // The sum over the heart's moves of its farthest vertex's displacement (unit: m).
  Real travel = 0;
  // How much farther than asked a search reaches when it may find the particle clear: a
  // particle clear by this much skips its searches until it or the heart moves as far (unit: m).
  Real reach = Real(0.002);
  std::uint64_t searched = 0, skipped = 0;  // the particles' queries, searched or answered
};

}  // namespace imasim::tissue
