#pragma once
// The thorax scene's fascia, and its vessel, solved by the implicit membrane step
// (physics/implicit_membrane.hpp) instead of their XPBD rows: the fascia with its
// strain-stiffening law (`fascia.solver = "implicit"`, use_implicit_fascia,
// tissue/implicit_fascia.hpp), the vessel with its own XPBD rows' energy (`vessel.solver =
// "implicit"`, use_implicit_vessel, tissue/implicit_rows.hpp). Each step, staggered, before the
// XPBD step of everything else, each such mesh in turn (the fascia first):
// - the heart's, the wall's and the floor's contact rows on the mesh become the implicit
//   step's fixed planes (each row's end-of-step surface point moved out by its margin), with the
//   row's kinetic friction pressed by the force the last step left there, and leave the XPBD set;
// - the instruments' proxies (physics/proxy_body.hpp) are bodies of the solve: their contact rows
//   on the mesh become planes that ride on them (with their friction, as the fixed planes'),
//   their grasp's holds on it stiff springs to
//   them, the surfaces that stop them (the heart, the chest wall: body stop rows) stiff one-sided
//   springs on them, each proxy on its coupling's spring and damper (eq. 17's virtual coupling);
// - the fat's columns under it (tissue/fat_support.hpp) are its supports; where the mesh is a
//   coupling's destination (the vessel, of the fat beside it), a strand an instrument holds
//   pulls the vertices it is coupled to (eq. 9 with beta = 1) as stiff holds at the coupling's
//   target, and otherwise (beta = 0) each such vertex is held to its reference by the spring
//   whose backward-Euler step is eq. 9's decay;
// - the mesh is stepped; a proxy it pushed or pulled gets its spring's rest moved so that the
//   XPBD step, in which the proxy meets the other tissues, carries it where the implicit
//   step left it (at rest, the mesh's force over k added to the spring): a block Gauss-Seidel
//   coupling;
// - its particles are held still (kinematic) while XPBD steps the rest, which reads
//   it as a boundary (the strands' ends, the couplings from it); the instruments' rows and
//   holds on it stay in the XPBD set, where the still mesh is an obstacle the proxy cannot
//   enter and a hold that keeps it (ContactRow::stops_body, BodyAttachmentRow::holds_body: the
//   other tissues cannot push the tool into it, nor a stop take it away from what it
//   holds, behind the implicit step's back), and get the implicit step's impulse and depth after,
//   so that every reader of the rows (the felt force, the contact events) sees the mesh as it
//   saw XPBD's.
// Then the masses and the implicit step's velocities are given back.
#include <cstdint>
#include <span>
#include <vector>

#include "physics/membrane_springs.hpp"
#include "physics/step.hpp"
#include "tissue/implicit_fascia.hpp"
#include "tissue/implicit_rows.hpp"

namespace imasim::scene {

struct ThoraxScene;

struct SceneImplicitMesh {
  std::uint32_t mesh = 0;  // in world.meshes: the fascia or the vessel
  // How the step is made from the mesh: the fascia's law (material, its edges' springs, and
  // flat hinges of bending_stiffness), kept to rebuild after a cut; or (own_rows) the mesh's
  // own XPBD rows, read once into rows (the vessel: a tube, curved at rest).
  bool own_rows = false;
  tissue::MeshRows rows;
  physics::StiffeningMembrane material;
  Real bending_stiffness = 0;  // D (unit: N m)
  tissue::ImplicitFascia solver;
  std::uint32_t built_revision = 0;  // the mesh's topology_revision the solver was built at
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
  // The instruments' holds (a body each), then eq. 9's holds where the mesh is a coupling's
  // destination (kNoMembraneBody: a held strand's pull, or the decay's spring to the reference).
  std::vector<physics::MembraneAttachment> attachments;
  std::size_t tool_holds = 0;                         // of the attachments, the instruments'
  std::vector<physics::MembraneBodyStop> body_stops;  // the proxies' at the heart and the wall
  std::vector<physics::MembraneSupport> supports;     // the fat's columns under the mesh
  std::vector<Vec3> attachment_pull;                  // on the body, each (unit: N)
  std::vector<physics::MembraneBody> bodies;          // one per proxy
  std::vector<Vec3> force_on_body;                    // the mesh's push and pull on each (unit: N)
  std::vector<std::uint8_t> touched;                  // whether the mesh pushed or pulled each
  // Coagulated tissue is stiffer (surgery/cautery.hpp): per mesh vertex, whether it is, and
  // per solver edge, whether its springs took the factor already (unit of the factor: 1).
  std::vector<std::uint8_t> coagulated, edge_stiffened;
  Real coagulated_factor = 1;
  std::vector<Real> inverse_mass;  // the mesh's, kept while XPBD steps
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

// Replaces the vessel's XPBD rows by the implicit step of the same rows' energy
// (tissue/implicit_rows.hpp). Set-up. Throws std::invalid_argument as rows_of_mesh does.
void use_implicit_vessel(ThoraxScene& scene);

// After a topology change of the fascia (tissue/topology_change.hpp: a cut, a fragment
// vaporised): the XPBD rows the change added are removed again, and the implicit step is rebuilt
// from the mesh as it now is (its new vertices, eq. 5's masses, its edges and hinges; the pattern
// analysed again). step_scene_implicit calls it when the mesh's topology_revision has moved on,
// so a caller that cuts need not. Nothing to do without the implicit fascia.
void refit_scene_fascia(ThoraxScene& scene);

// Coagulation (the session's cautery): the implicit meshes' edges with a coagulated end
// (`coagulated`: per particle of the world, from surgery::CauteryState) take stiffness times
// `factor` (the inverse of the XPBD rows' compliance factor), once; a refit after a cut keeps
// them stiff. Nothing to do without an implicit mesh.
void coagulate_scene_implicit(ThoraxScene& scene, std::span<const std::uint8_t> coagulated,
                              Real factor);

// The step's first part (finish_thorax_step calls it after the contacts are gathered): each
// implicit mesh refitted if it was cut since, its contacts taken out of the XPBD set, stepped,
// its particles made kinematic. A failed solve comes back as a non-finite status naming the
// mesh's first particle.
physics::StepResult step_scene_implicit(ThoraxScene& scene, const physics::Executor& exec);

// After the XPBD step: the implicit meshes' masses and velocities back; the instruments' rows
// and holds on them, and their proxies, given the implicit step's impulses.
void release_scene_implicit(ThoraxScene& scene);

}  // namespace imasim::scene
