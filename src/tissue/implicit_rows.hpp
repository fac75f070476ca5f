#pragma once
// A mesh object of the world as an implicit membrane (physics/implicit_membrane.hpp) whose
// energy is its own XPBD rows': each distance row (eq. 2) a spring of stiffness 1 / (alpha s) at
// its rest length, each dihedral row (eq. 3) a MembraneDihedral of k = 1 / (alpha s) at its rest
// angle, alpha the row's material compliance and s its compliance scale. XPBD converges to the
// minimum of this energy as its substeps shrink; Newton's method on the whole mesh at once
// reaches it in a step. For a mesh curved at rest (the vessel's tube), where the flat hinges of
// tissue/implicit_fascia.hpp do not apply; the masses and the fixed particles are the world's.
#include <cstdint>
#include <vector>

#include "physics/implicit_membrane.hpp"
#include "tissue/tissue_world.hpp"

namespace imasim::tissue {

// A mesh's XPBD rows as the implicit step's springs and hinges, mesh-local: read once, kept by a
// caller that removes the rows from XPBD and builds the solver again later (another body count).
struct MeshRows {
  std::uint32_t mesh = 0;  // in world.meshes
  std::vector<physics::MembraneEdge> edges;
  std::vector<physics::MembraneDihedral> dihedrals;
};

// Throws std::invalid_argument for a mesh out of range, a row of the mesh that is PBD or rigid
// (no compliance: no finite stiffness), or a row joining the mesh to another object's particle.
MeshRows rows_of_mesh(const TissueWorld& world, std::uint32_t mesh);

// The implicit step of rows.mesh with the world's masses and fixed particles as they are now.
// h: the step (unit: s); bodies: the MembraneBody count each step will bring.
physics::ImplicitMembrane implicit_membrane_of_rows(const TissueWorld& world, const MeshRows& rows,
                                                    Real h, std::uint32_t bodies = 0);

// rows_of_mesh and implicit_membrane_of_rows at once.
physics::ImplicitMembrane implicit_membrane_of_rows(const TissueWorld& world, std::uint32_t mesh,
                                                    Real h, std::uint32_t bodies = 0);

}  // namespace imasim::tissue
