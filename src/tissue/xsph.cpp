#include "tissue/xsph.hpp"

#include <cmath>

namespace imasim::tissue {

void smooth_strand_velocities(TissueWorld& world) {
  physics::Particles& P = world.state.particles;
  std::vector<Vec3>& out = world.xsph_scratch;
  for (const StrandSet& set : world.strands) {
    if (set.xsph_coefficient <= 0) continue;
    const std::uint32_t count = set.particle_count();
    const Real h = set.xsph_radius;
    for (std::uint32_t k = 0; k < count; ++k) {
      const std::uint32_t i = set.first_particle + k;
      out[i] = P.velocity[i];
      if (set.diameter[k] == 0) continue;  // removed by a cut
      Real weight = 0;
      Vec3 pull = Vec3::Zero();
      for (std::uint32_t n = set.neighbour_start[k]; n < set.neighbour_start[k + 1]; ++n) {
        if (set.diameter[set.neighbours[n]] == 0) continue;
        const std::uint32_t j = set.first_particle + set.neighbours[n];
        const Real r = (P.position[j] - P.position[i]).norm();
        if (r >= h) continue;
        const Real w = (1 - r / h) * (1 - r / h);
        weight += w;
        pull += w * (P.velocity[j] - P.velocity[i]);
      }
      if (weight > 0) out[i] += (set.xsph_coefficient / weight) * pull;
    }
    for (std::uint32_t k = 0; k < count; ++k) {
      P.velocity[set.first_particle + k] = out[set.first_particle + k];
    }
  }
}

}  // namespace imasim::tissue
