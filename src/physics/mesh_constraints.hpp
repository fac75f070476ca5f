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

// Throws std::invalid_argument if the mesh has non-manifold edges.
MeshConstraintCounts add_mesh_constraints(ConstraintSystem& cs, const Particles& particles,
                                          const geometry::EdgeAdjacency& adjacency,
                                          std::uint32_t first_particle, MaterialId stretch,
                                          MaterialId bend);

}  // namespace imasim::physics
