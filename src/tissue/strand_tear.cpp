#include "tissue/strand_tear.hpp"

#include <cmath>

namespace imasim::tissue {

std::uint32_t tear_overstretched_strands(TissueWorld& w, std::vector<StrandTear>& torn) {
  const physics::Particles& P = w.state.particles;
  std::uint32_t count = 0;
  for (std::uint32_t s = 0; s < w.strands.size(); ++s) {
    StrandSet& set = w.strands[s];
    for (std::uint32_t i = 0; i < set.strand_count; ++i) {
      if (set.cut[i] != kStrandIntact) continue;
      const std::uint32_t a = set.particle(i, 0), b = set.particle(i, set.segments);
      // Squared lengths: no root for the strands that hold (nearly all of them, every step).
      const Real rest2 = (P.rest_position[b] - P.rest_position[a]).squaredNorm();
      const Real now2 = (P.position[b] - P.position[a]).squaredNorm();
      if (!(now2 > set.tear_stretch * set.tear_stretch * rest2)) continue;
      for (std::uint32_t k = 0; k < set.segments; ++k)
        w.state.constraints.distance.remove(set.segment_constraint[i * set.segments + k]);
      set.cut[i] = kStrandTorn;
      torn.push_back({s, i, std::sqrt(now2 / rest2)});
      ++count;
    }
  }
  return count;
}

}  // namespace imasim::tissue
