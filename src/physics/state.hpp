#pragma once
// The mutable state of a simulation: what a step changes (positions, velocities, multipliers,
// constraint sets after topology changes, time), plus the step's preallocated scratch.
#include <cstdint>
#include <vector>

#include "physics/active_rows.hpp"
#include "physics/body_attachment.hpp"
#include "physics/body_stop.hpp"
#include "physics/constraint_system.hpp"
#include "physics/contact.hpp"
#include "physics/follow.hpp"
#include "physics/model.hpp"
#include "physics/particles.hpp"
#include "physics/proxy_body.hpp"
#include "physics/support_row.hpp"

namespace imasim::physics {

// An object's dynamic particles (inverse mass > 0) lie in [dynamic_first, dynamic_end), with
// others' possibly interleaved; found at the start of every step (step.cpp), so cuts that make
// spare particles dynamic are seen. dynamic_end == 0: none.
struct ObjectRange {
  std::uint32_t dynamic_first = 0, dynamic_end = 0;
};

// Buffers a step needs, sized by prepare_state() so that stepping never allocates.
struct StepScratch {
  std::vector<Vec3> saved_position;  // state at step start, restored if the step diverges
  std::vector<Vec3> saved_velocity;
  std::vector<ProjectionTerms> projection_terms;  // per material, for a fine substep
  std::vector<ProjectionTerms> coarse_terms;      // per material, for a coarse substep
  std::vector<ProjectionTerms> bending_terms;     // per material, fine bending (bending_stride)
  std::vector<Vec3>
      group_start;  // fine particles' positions as the step's last bending group began
  std::vector<Real> object_keep;                // per object: linear damping factor per substep
  std::vector<ObjectRange> object_ranges;       // per object, for per-object passes
  std::vector<std::uint32_t> block_first_bad;   // per particle chunk: first diverging particle
  std::vector<std::uint32_t> validation_stamp;  // per particle, for invariant checks
  // Contact, follow and body attachment rows are ordered band 0 first at the start of a step; band
  // 1 starts here.
  std::size_t contact_split = 0, follow_split = 0, body_attachment_split = 0;
  std::size_t support_split = 0;  // the same for the support rows
  // The two bands run side by side over each group of substeps (a coarse substep and the fine
  // ones it spans): per follow row, whether its source is in the other band than its
  // destination, and that source as the group began, which such a row reads instead.
  std::vector<std::uint8_t> follow_crosses;
  std::vector<Vec3> follow_sources;
  // The proxies as the group began, and the coarse band's copy of them, which its contacts move;
  // what they moved it by is added to the proxies when the bands join.
  std::vector<ProxyBody> group_proxies, coarse_proxies;
  // The coarse band's rows that its further sweeps visit, found once a step (active_rows.hpp).
  ActiveRows coarse_active;
};

struct State {
  Particles particles;
  ConstraintSystem constraints;
  ContactSet contacts;  // gathered before each step by the surfaces' owners, projected in it
  // The instruments' proxies (proxy_body.hpp), named by contact rows; set by their owner.
  std::vector<ProxyBody> proxies;
  // The heart and the chest wall stopping those bodies (body_stop.hpp); gathered by their owner.
  std::vector<BodyStopRow> body_stops;
  // Particles held by those bodies (body_attachment.hpp: the grasp); set by their owner.
  std::vector<BodyAttachmentRow> body_attachments;
  // With SolverParams::bending_stride > 1, a fine particle's stored velocity is its mean over
  // the step's last bending group (stride substeps): the velocity of the last substep alone
  // carries the strided bending's impulse in the substep that applies it, a saw-tooth of about
  // h f_bend / (2 m) at rest. The solver's own velocity is the stored one plus this offset,
  // added back at the next step's start, so its dynamics are the strided scheme's exactly.
  std::vector<Vec3> velocity_offset;  // (unit: m/s); 0 for coarse and fixed particles
  std::vector<FollowRow> follows;     // refreshed before each step by the couplings' owner
  // Columns holding particles off a fixed base (support_row.hpp); gathered before each step by
  // their owner (tissue/fat_support.hpp).
  std::vector<SupportRow> supports;
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
