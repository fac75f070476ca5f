#pragma once
// Bidirectional offset coupling (2.3.3, eq. 8-9). Offsets are displacements from the rest
// configuration, O = x - x0. A coupling is a precomputed list of (source, destination) particle
// pairs, so nothing is searched while running. Each step:
//   source -> destination (eq. 8, and eq. 9 with beta = 1):
//       O_dst = O_src / |O_src| * min(|O_src|, lambda_max)
//   with beta = 0 the destination instead relaxes:  O_dst <- decay * O_dst  (eq. 9, 0.8)
// Both per 5 ms step, as the paper applies them, after the solver.
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "physics/follow.hpp"
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
// moved by a boundary condition such as the heart's drive. Position and velocity agree (SPEC S2
// reading): a destination's velocity becomes its motion over the step, (x_new - x_start) / dt,
// with x_start its position at the step's start (`start`). Were only the position moved (or the
// velocity changed by the last substep's share), the next step would carry the solver's motion
// that the coupling undid: a decaying vessel would never stop, a coupled fat point would keep a
// velocity it does not have. With `start` empty only positions change. Destinations flagged in
// `held` (grasped: they follow the jaws) are left alone.
void apply_coupling(const OffsetCoupling& c, physics::Particles& particles,
                    const std::vector<Vec3>& reference, std::span<const Vec3> start, Real dt,
                    std::span<const std::uint8_t> held = {});
inline void apply_coupling(const OffsetCoupling& c, physics::Particles& particles) {
  apply_coupling(c, particles, particles.rest_position, {}, Real(0));
}

// The follow rows (physics/follow.hpp) of an active coupling (beta = 1, eq. 8 and 9) for the
// coming step, appended to `out`: each pair whose destination is not held, with the step's
// references. A coupling that is not active (beta = 0) adds nothing: its decay is applied after
// the step (apply_coupling).
void append_follow_rows(const OffsetCoupling& c, const std::vector<Vec3>& reference,
                        std::span<const std::uint8_t> held, std::vector<physics::FollowRow>& out);

// Pairs each destination particle with its nearest source particle (by rest position), using a
// spatial grid; destinations with no source within `radius` (unit: m) are left out.
std::vector<std::pair<std::uint32_t, std::uint32_t>> nearest_source_pairs(
    const physics::Particles& particles, const std::vector<std::uint32_t>& sources,
    const std::vector<std::uint32_t>& destinations, Real radius);

}  // namespace imasim::tissue
