#pragma once
// The thorax scene's fascia solved by the implicit membrane step (tissue/implicit_fascia.hpp)
// instead of its XPBD rows (`fascia.solver = "implicit"`, or use_implicit_fascia). Each step,
// staggered, before the XPBD step of everything else:
// - the heart's, the wall's and the floor's contact rows on the fascia become the implicit
//   step's fixed planes (each row's end-of-step surface point moved out by its margin), with the
//   row's kinetic friction pressed by the force the last step left there, and leave the XPBD set;
// - the instruments' proxies (physics/proxy_body.hpp) are bodies of the solve: their contact rows
//   on the fascia become planes that ride on them (with their friction, as the fixed planes'),
//   their grasp's holds on it stiff springs to
//   them, the surfaces that stop them (the heart, the chest wall: body stop rows) stiff one-sided
//   springs on them, each proxy on its coupling's spring and damper (eq. 17's virtual coupling);
// - the fascia is stepped; a proxy it pushed or pulled gets its spring's rest moved so that the
//   XPBD step, in which the proxy meets the vessel and the fat, carries it where the implicit
//   step left it (at rest, the fascia's force over k added to the spring): a block Gauss-Seidel
//   coupling;
// - its particles are held still (kinematic) while XPBD steps the vessel and the fat, which read
//   it as a boundary (the strands' ends, the fascia -> fat coupling); the instruments' rows and
//   holds on it stay in the XPBD set, where the still fascia is an obstacle the proxy cannot
//   enter and a hold that keeps it (ContactRow::stops_body, BodyAttachmentRow::holds_body: the
//   vessel and the fat cannot push the tool into the fascia, nor a stop take it away from what it
//   holds, behind the implicit step's back), and get the implicit step's impulse and depth after,
//   so that every reader of the rows (the felt force, the contact events) sees the fascia as it
//   saw XPBD's.
// Then the fascia's masses and the implicit step's velocities are given back.
#include <cstdint>
#include <span>
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
  Real largest_residual = 0;  // over every step so far (unit: N)
  // Over every step so far: Newton iterations, factorisations, solver rebuilds after a cut.
  std::uint64_t steps = 0, iterations = 0, factorizations = 0, refits = 0;
  // Of those: factorisations for a changed active set, iterations whose line search shortened
  // the Newton step (physics::ImplicitStepReport).
  std::uint64_t active_set_factorizations = 0, shortened_iterations = 0;
  std::uint32_t built_bodies = 0;  // the proxies the solver was built for
  // Scratch, sized at set-up. The contacts: the fixed planes first, then the instruments' rows,
  // whose tags (marked while the XPBD step runs) are kept in tool_tags, in the same order.
  std::vector<physics::MembraneContact> contacts;
  std::vector<std::uint32_t> tool_tags;
  std::vector<Real> tool_depth;  // how deep each tool row's vertex ended inside (unit: m)
  std::vector<physics::MembraneAttachment> attachments;
  std::vector<physics::MembraneBodyStop> body_stops;  // the proxies' at the heart and the wall
  std::vector<physics::MembraneSupport> supports;     // the fat's columns under the fascia
  std::vector<Vec3> attachment_pull;                  // on the body, each (unit: N)
  std::vector<physics::MembraneBody> bodies;          // one per proxy
  std::vector<Vec3> force_on_body;    // the fascia's push and pull on each (unit: N)
  std::vector<std::uint8_t> touched;  // whether the fascia pushed or pulled each
  // Coagulated tissue is stiffer (surgery/cautery.hpp): per mesh vertex, whether it is, and
  // per solver edge, whether its springs took the factor already (unit of the factor: 1).
  std::vector<std::uint8_t> coagulated, edge_stiffened;
  Real coagulated_factor = 1;
  std::vector<Real> inverse_mass;  // the fascia's, kept while XPBD steps
  std::vector<Vec3> velocity;
  // Friction's lagged normal force (physics::MembraneContact::normal_force): each contact's surface
  // (its row's tag), in the contacts' order, and the force each vertex was pressed with by each
  // surface at the last step's end, sorted by vertex and surface.
  struct PressedVertex {
    std::uint32_t vertex = 0, tag = 0;
    Real force = 0;  // (unit: N)
  };
  std::vector<std::uint32_t> contact_tags;
  std::vector<PressedVertex> pressed;
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

// Coagulation (the session's cautery): the fascia's edges with a coagulated end (`coagulated`:
// per particle of the world, from surgery::CauteryState) take stiffness times `factor` (the
// inverse of the XPBD rows' compliance factor), once; a refit after a cut keeps them stiff.
// Nothing to do without the implicit fascia.
void coagulate_scene_fascia(ThoraxScene& scene, std::span<const std::uint8_t> coagulated,
                            Real factor);

// The step's first part (finish_thorax_step calls it after the contacts are gathered): the solver
// refitted if the fascia was cut since, the fascia's contacts taken out of the XPBD set, the
// fascia stepped, its particles made kinematic.
// A failed solve comes back as a non-finite status naming the fascia's first particle.
physics::StepResult step_scene_fascia(ThoraxScene& scene);

// After the XPBD step: the fascia's masses and velocities back; the instruments' rows and holds
// on it, and their proxies, given the implicit step's impulses.
void release_scene_fascia(ThoraxScene& scene);

}  // namespace imasim::scene
