#include "physics/mesh_constraints.hpp"

#include <stdexcept>
#include <string>

namespace imasim::physics {

MeshConstraintCounts add_mesh_constraints(ConstraintSystem& cs, const Particles& particles,
                                          const geometry::EdgeAdjacency& adjacency,
                                          std::uint32_t first_particle, MaterialId stretch,
                                          MaterialId bend) {
  if (!adjacency.non_manifold_edges.empty()) {
    const auto& e = adjacency.non_manifold_edges.front();
    throw std::invalid_argument("mesh is not a manifold: edge " + std::to_string(e[0]) + "-" +
                                std::to_string(e[1]) + " is shared by more than two faces");
  }
  MeshConstraintCounts counts;
  for (const geometry::MeshEdge& e : adjacency.edges) {
    add_distance(cs, particles, first_particle + e.a, first_particle + e.b, stretch);
    ++counts.distance;
  }
  for (const geometry::MeshEdge& e : adjacency.edges) {
    if (!e.is_interior()) continue;
    // faces[0] traverses a->b, so its wing is p0 and the other face's wing is p1 (eq. 3).
    add_dihedral(cs, particles, first_particle + e.opposite[0], first_particle + e.opposite[1],
                 first_particle + e.a, first_particle + e.b, bend);
    ++counts.dihedral;
  }
  return counts;
}

}  // namespace imasim::physics
