#pragma once
// A triangle mesh's edges as strain-stiffening springs of a membrane in physical units, for the
// implicit membrane solve (implicit_membrane.hpp): the same mapping as the XPBD stretch rows
// (membrane_material.hpp), k_e = E t sum_T A_T / |e|^2, once with the toe-region modulus and once
// with the linear-region one, so that the sheet's modulus does not depend on the mesh.
#include <vector>

#include "geometry/triangle_mesh.hpp"
#include "physics/implicit_membrane.hpp"

namespace imasim::physics {

struct StiffeningMembrane {
  Real toe_modulus = 0;     // E in the toe region (unit: Pa)
  Real linear_modulus = 0;  // E past the toe strain (unit: Pa)
  Real toe_strain = 0;      // where the toe ends (dimensionless)
  Real thickness = 0;       // t (unit: m)
  Real density = 0;         // rho, for the lumped masses (unit: kg/m^3)
};

// One spring per unique edge, in build_edge_adjacency's order. Throws std::invalid_argument
// naming an edge of zero length.
std::vector<MembraneEdge> membrane_springs(const geometry::TriangleMesh& mesh,
                                           const StiffeningMembrane& material);

// One hinge per interior edge, in build_edge_adjacency's order, for a mesh flat at rest: the
// weights of MembraneHinge from the rest geometry, k = D |e|^2 / (A_1 + A_2) as the XPBD
// dihedral rows (membrane_material.hpp). D: the bending stiffness (unit: N m). Throws
// std::invalid_argument naming an edge whose wing lies on it or whose hinge is not flat at rest
// (its rest dihedral angle above 1e-6 rad): this bending would push such a hinge flat.
std::vector<MembraneHinge> membrane_hinges(const geometry::TriangleMesh& mesh,
                                           Real bending_stiffness);

// Lumped masses: a third of each triangle's rho t A to each of its corners (unit: kg).
std::vector<Real> membrane_masses(const geometry::TriangleMesh& mesh,
                                  const StiffeningMembrane& material);

}  // namespace imasim::physics
