#pragma once
// Invariant checks: cheap ones for loaders and set-up, expensive ones (every constraint, every
// colour) that the solver runs at each step when built with IMASIM_VALIDATION (CI does).
#include <string>

#include "physics/model.hpp"
#include "physics/state.hpp"

namespace imasim::physics {

// Empty when usable; else a message naming the offending field.
std::string validate_model(const Model& model);

// Particles refer to existing objects, constraints to existing particles and materials, every
// regular colour holds each particle at most once and the particle colour masks agree.
// Uses state.scratch.validation_stamp (prepare_state sizes it) so that it does not allocate.
std::string validate_state(const Model& model, State& state);

}  // namespace imasim::physics
