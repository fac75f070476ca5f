#pragma once
// A mesh object of the world as an implicit membrane (physics/implicit_membrane.hpp) whose
// energy is its own XPBD rows': each distance row (eq. 2) a spring of stiffness 1 / (alpha s) at
// its rest length, each dihedral row (eq. 3) a MembraneDihedral of k = 1 / (alpha s) at its rest
// angle, alpha the row's material compliance and s its compliance scale. XPBD converges to the
// minimum of this energy as its substeps shrink; Newton's method on the whole mesh at once
// reaches it in a step. For a mesh curved at rest (the vessel's tube), where the flat hinges of
// tissue/implicit_fascia.hpp do not apply; the masses and the fixed particles are the world's.
#include <cstdint>

#include "physics/implicit_membrane.hpp"
#include "tissue/tissue_world.hpp"

namespace imasim::tissue {

// Throws std::invalid_argument for a mesh out of range, a row of the mesh that is PBD or rigid
// (no compliance: no finite stiffness), or a row joining the mesh to another object's particle.
// h: the step (unit: s); bodies: the MembraneBody count each step will bring.
physics::ImplicitMembrane implicit_membrane_of_rows(const TissueWorld& world, std::uint32_t mesh,
                                                    Real h, std::uint32_t bodies = 0);

}  // namespace imasim::tissue
