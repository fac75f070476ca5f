#pragma once
// The thorax scene's fascia solved by the implicit membrane step (tissue/implicit_fascia.hpp)
// instead of its XPBD rows, for tissue-only runs (tests and benches: the session's instruments
// do not reach it yet, docs/physics.md). Each step, before the XPBD step of everything else:
// the heart's, the wall's and the floor's contact rows on the fascia become the implicit step's
// frictionless contact planes (each row's end-of-step surface point moved out by its margin) and
// leave the XPBD set; the fascia is stepped; then its particles are held still (kinematic) while
// XPBD steps the vessel and the fat, which read it as a boundary (the strands' ends, the
// fascia -> fat coupling), and given back their mass and the implicit step's velocity after.
#include <cstdint>
#include <vector>

#include "physics/membrane_springs.hpp"
#include "physics/step.hpp"
#include "tissue/implicit_fascia.hpp"

namespace imasim::scene {

struct ThoraxScene;

struct SceneImplicitFascia {
  tissue::ImplicitFascia fascia;
  physics::StiffeningMembrane material;  // the edges' law, kept to rebuild after a cut
  Real bending_stiffness = 0;            // D (unit: N m)
  std::uint32_t built_revision = 0;      // the mesh's topology_revision the solver was built at
  physics::ImplicitSolveParams solve;
  physics::ImplicitStepReport last;
  // Steps whose Newton solve ran out of iterations above the tolerance (last.residual says by how
  // much): rare buckling of the slack fascia, counted so a run can report it.
  std::uint64_t unsolved_steps = 0;
  std::vector<physics::MembraneContact> contacts;  // scratch, sized at set-up
  std::vector<Real> inverse_mass;                  // the fascia's, kept while XPBD steps
  std::vector<Vec3> velocity;
};

// Replaces the fascia's XPBD rows (distance and dihedral: removed from the constraint system) by
// the implicit step with `material` and the fascia's own bending stiffness. Set-up; cuts after it
// are refitted by the step (refit_scene_fascia). Throws std::invalid_argument as
// make_implicit_fascia does.
void use_implicit_fascia(ThoraxScene& scene, const physics::StiffeningMembrane& material);

// After a topology change of the fascia (tissue/topology_change.hpp: a cut, a fragment
// vaporised): the XPBD rows the change added are removed again, and the implicit step is rebuilt
// from the mesh as it now is (its new vertices, eq. 5's masses, its edges and hinges; the pattern
// analysed again). step_scene_fascia calls it when the mesh's topology_revision has moved on, so
// a caller that cuts need not. Nothing to do without the implicit fascia.
void refit_scene_fascia(ThoraxScene& scene);

// The step's first part (finish_thorax_step calls it after the contacts are gathered): the solver
// refitted if the fascia was cut since, the fascia's contacts taken out of the XPBD set, the
// fascia stepped, its particles made kinematic.
// A failed solve comes back as a non-finite status naming the fascia's first particle.
physics::StepResult step_scene_fascia(ThoraxScene& scene);

// After the XPBD step: the fascia's masses and velocities back.
void release_scene_fascia(ThoraxScene& scene);

}  // namespace imasim::scene
