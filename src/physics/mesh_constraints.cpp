#include "physics/mesh_constraints.hpp"

#include "physics/membrane_material.hpp"

#include <stdexcept>
#include <string>

namespace imasim::physics {

Real rest_triangle_area(const Particles& particles, std::uint32_t first,
                        const geometry::Triangle& t) {
  const auto& x = particles.rest_position;
  return Real(0.5) *
         (x[first + t[1]] - x[first + t[0]]).cross(x[first + t[2]] - x[first + t[0]]).norm();
}

MeshConstraintCounts add_mesh_constraints(ConstraintSystem& cs, const Particles& particles,
                                          const geometry::TriangleMesh& mesh,
                                          const geometry::EdgeAdjacency& adjacency,
                                          std::uint32_t first_particle, MaterialId stretch,
                                          MaterialId bend, CompliancePerRow per_row) {
  if (!adjacency.non_manifold_edges.empty()) {
    const auto& e = adjacency.non_manifold_edges.front();
    throw std::invalid_argument("mesh is not a manifold: edge " + std::to_string(e[0]) + "-" +
                                std::to_string(e[1]) + " is shared by more than two faces");
  }
  MeshConstraintCounts counts;
  const bool membrane = per_row == CompliancePerRow::membrane;
  // |e|^2 and the rest area of the triangles on e, for the membrane scales.
  auto geometry_of = [&](const geometry::MeshEdge& e, Real& length2, Real& area) {
    const auto& x = particles.rest_position;
    length2 = (x[first_particle + e.a] - x[first_particle + e.b]).squaredNorm();
    area = 0;
    for (std::uint32_t f : e.faces)
      if (f != geometry::kNoFace)
        area += rest_triangle_area(particles, first_particle, mesh.triangles[f]);
  };
  for (const geometry::MeshEdge& e : adjacency.edges) {
    Real length2 = 0, area = 0;
    if (membrane) geometry_of(e, length2, area);
    add_distance(cs, particles, first_particle + e.a, first_particle + e.b, stretch,
                 membrane ? stretch_compliance_scale(length2, area) : Real(1));
    ++counts.distance;
  }
  for (const geometry::MeshEdge& e : adjacency.edges) {
    if (!e.is_interior()) continue;
    Real length2 = 0, area = 0;
    if (membrane) geometry_of(e, length2, area);
    // faces[0] traverses a->b, so its wing is p0 and the other face's wing is p1 (eq. 3).
    add_dihedral(cs, particles, first_particle + e.opposite[0], first_particle + e.opposite[1],
                 first_particle + e.a, first_particle + e.b, bend,
                 membrane ? bend_compliance_scale(length2, area) : Real(1));
    ++counts.dihedral;
  }
  return counts;
}

}  // namespace imasim::physics
