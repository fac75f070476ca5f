#pragma once
// The mutable state of a simulation: what a step changes (positions, velocities, multipliers,
// constraint sets after topology changes, time), plus the step's preallocated scratch.
#include <cstdint>
#include <vector>

#include "physics/constraint_system.hpp"
#include "physics/model.hpp"
#include "physics/particles.hpp"

namespace imasim::physics {

// Per-object sums for angular damping (eq. 4), accumulated serially in particle order.
struct ObjectMoments {
  Real mass = 0;
  Vec3 mass_position = Vec3::Zero();  // sum m x
  Vec3 momentum = Vec3::Zero();       // sum m v
  Vec3 angular_momentum = Vec3::Zero();
  Mat3 inertia = Mat3::Zero();
  Vec3 delta_omega = Vec3::Zero();  // change of the rigid rotation this substep (unit: rad/s)
};

// Buffers a step needs, sized by prepare_state() so that stepping never allocates.
struct StepScratch {
  std::vector<Vec3> saved_position;  // state at step start, restored if the step diverges
  std::vector<Vec3> saved_velocity;
  std::vector<ProjectionTerms> projection_terms;  // per material, for the current substep
  std::vector<ObjectMoments> object_moments;
  std::vector<std::uint32_t> block_first_bad;   // per particle block: first diverging particle
  std::vector<std::uint32_t> validation_stamp;  // per particle, for invariant checks
};

struct State {
  Particles particles;
  ConstraintSystem constraints;
  double time = 0;  // (unit: s)
  std::uint64_t step_count = 0;
  StepScratch scratch;
};

// Sizes the scratch for the model and the current particle and material counts. Called after
// set-up and after topology changes; step() also calls it, and it allocates only if they grew.
void prepare_state(const Model& model, State& state);

// Particles per block for the per-particle passes (fixed, so reductions are thread-independent).
inline constexpr std::size_t kParticleBlock = 2048;

// Hash of the particle positions, bit-exact (see math/state_hash.hpp).
std::uint64_t position_hash(const State& state);

}  // namespace imasim::physics
