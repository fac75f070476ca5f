#pragma once
// One step of the soft-tissue engine (SPEC S1): for each of n substeps of length h = dt/n,
// predict (eq. 1), project every constraint k times colour by colour, derive velocities, damp
// (eq. 4). A step that would leave a non-finite value or a particle faster than max_speed
// returns a failing status and leaves the state exactly as it was before the step.
#include <cstdint>

#include "physics/executor.hpp"
#include "physics/handle.hpp"
#include "physics/model.hpp"
#include "physics/state.hpp"
#include "physics/step_profile.hpp"

namespace imasim::physics {

enum class StepStatus : std::uint8_t {
  ok,
  non_finite,     // a position or velocity became NaN or infinite
  speed_limit,    // a particle exceeded SolverParams::max_speed
  invalid_state,  // an invariant check failed (IMASIM_VALIDATION builds)
};

const char* to_string(StepStatus status);

struct StepResult {
  StepStatus status = StepStatus::ok;
  std::uint32_t particle = kInvalidIndex;  // first offending particle, if any
  std::uint32_t substep = 0;               // substep in which it happened
  StepProfile profile;                     // the engine's stages; callers add their own

  bool ok() const { return status == StepStatus::ok; }
};

StepResult step(const Model& model, State& state, Executor& exec);

}  // namespace imasim::physics
