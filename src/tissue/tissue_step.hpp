#pragma once
// One step of the thoracic-wall tissues (ARCHITECTURE step items 5-6): the engine step, XSPH
// smoothing of the fat, the offset couplings (eq. 8-9), then normals, strand ends and visual
// meshes refreshed from the new positions. Allocation-free after set-up.
#include "physics/executor.hpp"
#include "physics/step.hpp"
#include "tissue/tissue_world.hpp"

namespace imasim::tissue {

// Call once after building (or changing) the world: sizes the solver scratch and places the
// strand ends and visual meshes.
void finish_setup(TissueWorld& world);

physics::StepResult step_tissue(TissueWorld& world, physics::Executor& exec);

// The two halves of step_tissue, for callers that act in between (the heart's collider):
// engine step, XSPH and couplings; then surfaces, visual meshes and strand ends.
physics::StepResult step_tissue_dynamics(TissueWorld& world, physics::Executor& exec);
void finish_tissue_step(TissueWorld& world, const physics::Executor& exec);
void finish_tissue_step(TissueWorld& world);  // on the calling thread alone

// world.manipulated: every particle of a strand of which an instrument holds a particle (the
// step marks it first; a caller acting before the step, on this step's holds, may too).
void mark_manipulated(TissueWorld& world);

// Recomputes vertex normals of the mesh objects and the fine visual meshes: the heaviest mesh
// beside the others on a team of two, the same bits on any thread count.
void update_surfaces(TissueWorld& world, const physics::Executor& exec);
void update_surfaces(TissueWorld& world);  // on the calling thread alone

}  // namespace imasim::tissue
