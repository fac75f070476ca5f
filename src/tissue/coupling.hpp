#pragma once
// Bidirectional offset coupling (2.3.3, eq. 8-9). Offsets are displacements from the rest
// configuration, O = x - x0. A coupling is a precomputed list of (source, destination) particle
// pairs, so nothing is searched while running. Each step:
//   source -> destination (eq. 8, and eq. 9 with beta = 1):
//       O_dst = O_src / |O_src| * min(|O_src|, lambda_max)
//   with beta = 0 the destination instead relaxes:  O_dst <- decay * O_dst  (eq. 9, 0.8)
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "physics/particles.hpp"

namespace imasim::tissue {

struct OffsetCoupling {
  std::string name;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;  // (source j, destination i)
  Real lambda_max = Real(0.01);                                // largest offset passed on (unit: m)
  bool active = true;      // beta: true = follow the source, false = decay
  Real decay = Real(0.8);  // eq. 9's factor for beta = 0
};

// Applies one coupling to the particles' positions (destinations only; sources are read).
// Offsets are measured from `reference` (per particle): the rest positions, or rest positions
// moved by a boundary condition such as the heart's drive.
void apply_coupling(const OffsetCoupling& c, physics::Particles& particles,
                    const std::vector<Vec3>& reference);
inline void apply_coupling(const OffsetCoupling& c, physics::Particles& particles) {
  apply_coupling(c, particles, particles.rest_position);
}

// Pairs each destination particle with its nearest source particle (by rest position), using a
// spatial grid; destinations with no source within `radius` (unit: m) are left out.
std::vector<std::pair<std::uint32_t, std::uint32_t>> nearest_source_pairs(
    const physics::Particles& particles, const std::vector<std::uint32_t>& sources,
    const std::vector<std::uint32_t>& destinations, Real radius);

}  // namespace imasim::tissue
