#pragma once
// Bidirectional offset coupling (2.3.3, eq. 8-9). Offsets are displacements from the rest
// configuration, O = x - x0. A coupling is a precomputed list of (source, destination) particle
// pairs, so nothing is searched while running. Each step:
//   source -> destination (eq. 8, and eq. 9 with beta = 1), inside the solve:
//       O_dst = O_src / |O_src| * min(|O_src|, lambda_max)
//   with beta = 0 the destination instead relaxes:  O_dst <- decay * O_dst  (eq. 9, 0.8), after
//   the step (decay 1: left to its own physics).
// beta is the coupling state indicator of eq. 9 (SPEC S2 reading): always 0, always 1,
// or per pair 1 while the source's strand is manipulated (an instrument holds a particle of it),
// so that retracting the fat moves the vessel and the fascia it is bound to, and they relax to
// rest once it is let go. Manipulated fat is driven by the tool: couplings that `yield` leave
// such destinations alone (no loop: a strand is either driven by the surface or drives it).
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "physics/follow.hpp"
#include "physics/particles.hpp"

namespace imasim::tissue {

enum class Beta : std::uint8_t {
  zero,         // the destination relaxes (eq. 9, beta = 0)
  one,          // the destination follows the source (eq. 8; eq. 9, beta = 1)
  manipulated,  // per pair: one while the source is manipulated, else zero
};

struct OffsetCoupling {
  std::string name;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;  // (source j, destination i)
  Real lambda_max = Real(0.01);                                // largest offset passed on (unit: m)
  Beta beta = Beta::one;
  Real decay = Real(0.8);  // eq. 9's factor for beta = 0 (1: none)
  bool yield = false;      // leave destinations that are manipulated to the tool
};

// Per particle flags of a step: held by an instrument (grasped: they follow the jaws, not the
// couplings) and manipulated (of a strand a held particle belongs to). Empty spans: none.
struct CouplingFlags {
  std::span<const std::uint8_t> held;
  std::span<const std::uint8_t> manipulated;
};

// Whether pair (j, i) of `c` follows its source in this step (beta 1) or, if not, relaxes.
inline bool pair_follows(const OffsetCoupling& c, std::uint32_t j, const CouplingFlags& f) {
  if (c.beta == Beta::manipulated) return j < f.manipulated.size() && f.manipulated[j];
  return c.beta == Beta::one;
}

// Eq. 8 (and eq. 9, beta = 1): where destination i is put by source j, the source's offset O_j
// passed on, its length clamped to lambda_max (unit: m).
inline Vec3 follow_target(const OffsetCoupling& c, const Vec3& source, const Vec3& source_reference,
                          const Vec3& reference) {
  const Vec3 offset = source - source_reference;  // O_j
  const Real len = offset.norm();
  return len > c.lambda_max ? Vec3(reference + (c.lambda_max / len) * offset)
                            : Vec3(reference + offset);
}

// Eq. 9, beta = 0: the destination's offset shrunk by the decay (unit: m).
inline Vec3 relaxed_target(const OffsetCoupling& c, const Vec3& position, const Vec3& reference) {
  return reference + c.decay * (position - reference);
}

// Eq. 9, beta = 0, for a solver that steps the destination implicitly: the spring to its
// reference whose backward-Euler step over h decays a lone particle's offset by c.decay, as
// relaxed_target does after the step (m / h^2 (x1 - x0) + k (x1 - ref) = 0 gives x1 - ref =
// d (x0 - ref) for k = m / h^2 (1 - d) / d). mass (unit: kg), h (unit: s); (unit: N/m).
inline Real decay_spring_stiffness(const OffsetCoupling& c, Real mass, Real h) {
  return mass / (h * h) * (1 - c.decay) / c.decay;
}

// Whether destination i is left alone by `c` in this step: held, or manipulated and `c` yields.
inline bool destination_left(const OffsetCoupling& c, std::uint32_t i, const CouplingFlags& f) {
  if (i < f.held.size() && f.held[i]) return true;
  return c.yield && i < f.manipulated.size() && f.manipulated[i];
}

// Applies one coupling to the particles' positions (destinations only; sources are read): the
// pairs that follow their source (beta 1) and, with `relaxing`, those that relax (beta 0) instead.
// Offsets are measured from `reference` (per particle): the rest positions, or rest positions
// moved by a boundary condition such as the heart's drive. Position and velocity agree (SPEC S2
// reading): a destination's velocity becomes its motion over the step, (x_new - x_start) / dt,
// with x_start its position at the step's start (`start`). Were only the position moved (or the
// velocity changed by the last substep's share), the next step would carry the solver's motion
// that the coupling undid: a decaying vessel would never stop, a coupled fat point would keep a
// velocity it does not have. With `start` empty only positions change. Destinations left alone
// (destination_left) and fixed ones are not moved.
enum class PairsApplied : std::uint8_t { following, relaxing, all };
void apply_coupling(const OffsetCoupling& c, physics::Particles& particles,
                    const std::vector<Vec3>& reference, std::span<const Vec3> start, Real dt,
                    const CouplingFlags& flags, PairsApplied which);
inline void apply_coupling(const OffsetCoupling& c, physics::Particles& particles) {
  apply_coupling(c, particles, particles.rest_position, {}, Real(0), {}, PairsApplied::all);
}

// The follow rows (physics/follow.hpp) of the pairs of `c` that follow their source in the coming
// step (beta 1, eq. 8 and 9), appended to `out`, with the step's references; the others relax
// after the step (apply_coupling). Destinations left alone and fixed ones get none.
void append_follow_rows(const OffsetCoupling& c, const physics::Particles& particles,
                        const std::vector<Vec3>& reference, const CouplingFlags& flags,
                        std::vector<physics::FollowRow>& out);

// Pairs each destination particle with its nearest source particle (by rest position), using a
// spatial grid; destinations with no source within `radius` (unit: m) are left out.
std::vector<std::pair<std::uint32_t, std::uint32_t>> nearest_source_pairs(
    const physics::Particles& particles, const std::vector<std::uint32_t>& sources,
    const std::vector<std::uint32_t>& destinations, Real radius);

}  // namespace imasim::tissue
