#pragma once
// Builds a membrane's constraints from its triangle mesh: a distance constraint (eq. 2) on every
// edge and a dihedral constraint (eq. 3) on every interior edge. Mesh vertex v is particle
// first_particle + v.
#include <cstdint>

#include "geometry/edge_adjacency.hpp"
#include "geometry/triangle_mesh.hpp"
#include "physics/constraint_system.hpp"

namespace imasim::physics {

struct MeshConstraintCounts {
  std::size_t distance = 0;
  std::size_t dihedral = 0;
};

// How each row's compliance relates to its material's.
enum class CompliancePerRow : std::uint8_t {
  material,  // every row has the material's compliance as given (raw, the cloth scene)
  membrane,  // scaled by the rest geometry of the edge (physics/membrane_material.hpp)
};

// Throws std::invalid_argument if the mesh has non-manifold edges.
MeshConstraintCounts add_mesh_constraints(ConstraintSystem& cs, const Particles& particles,
                                          const geometry::TriangleMesh& mesh,
                                          const geometry::EdgeAdjacency& adjacency,
                                          std::uint32_t first_particle, MaterialId stretch,
                                          MaterialId bend, CompliancePerRow per_row);

// Rest area of a mesh-local triangle (first_particle + vertex is its particle) (unit: m^2).
Real rest_triangle_area(const Particles& particles, std::uint32_t first_particle,
                        const geometry::Triangle& t);

}  // namespace imasim::physics
