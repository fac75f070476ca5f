#include "physics/membrane_springs.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "geometry/edge_adjacency.hpp"

namespace imasim::physics {

namespace {

std::string edge_name(const geometry::MeshEdge& e) {
  return "membrane edge " + std::to_string(e.a) + "-" + std::to_string(e.b);
}

Real triangle_area(const geometry::TriangleMesh& mesh, std::uint32_t f) {
  const auto& t = mesh.triangles[f];
  const Vec3& a = mesh.vertices[t[0]];
  return Real(0.5) * (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
}

}  // namespace

std::vector<MembraneEdge> membrane_springs(const geometry::TriangleMesh& mesh,
                                           const StiffeningMembrane& material) {
  const geometry::EdgeAdjacency adjacency = geometry::build_edge_adjacency(mesh);
  std::vector<MembraneEdge> springs;
  springs.reserve(adjacency.edges.size());
  for (const geometry::MeshEdge& e : adjacency.edges) {
    Real area = 0;
    for (std::uint32_t f : e.faces)
      if (f != geometry::kNoFace) area += triangle_area(mesh, f);
    const Real length2 = (mesh.vertices[e.a] - mesh.vertices[e.b]).squaredNorm();
    if (!(length2 > 0)) throw std::invalid_argument(edge_name(e) + " has no length");
    // k_e = E t sum_T A_T / |e|^2 (unit: N/m)
    const Real per_modulus = material.thickness * area / length2;
    MembraneEdge spring;
    spring.i = e.a;
    spring.j = e.b;
    spring.spring.rest_length = std::sqrt(length2);
    spring.spring.toe_stiffness = material.toe_modulus * per_modulus;
    spring.spring.linear_stiffness = material.linear_modulus * per_modulus;
    spring.spring.toe_strain = material.toe_strain;
    springs.push_back(spring);
  }
  return springs;
}

std::vector<MembraneHinge> membrane_hinges(const geometry::TriangleMesh& mesh,
                                           Real bending_stiffness) {
  const geometry::EdgeAdjacency adjacency = geometry::build_edge_adjacency(mesh);
  std::vector<MembraneHinge> hinges;
  for (const geometry::MeshEdge& e : adjacency.edges) {
    if (!e.is_interior()) continue;
    MembraneHinge hinge;
    hinge.v = {e.a, e.b, e.opposite[0], e.opposite[1]};
    const Vec3& a = mesh.vertices[e.a];
    const Vec3 edge = mesh.vertices[e.b] - a;
    const Real length = edge.norm();
    if (!(length > 0)) throw std::invalid_argument(edge_name(e) + " has no length");
    const Vec3 t = edge / length;
    // Each wing's place along the edge (s) and its height over it (h): w = 1/h for the wings,
    // and the edge's ends take what makes the sum and the first moment vanish at rest.
    Real along = 0;
    for (int k = 0; k < 2; ++k) {
      const Vec3 r = mesh.vertices[e.opposite[k]] - a;
      const Real s = r.dot(t), h = (r - s * t).norm();
      if (!(h > 0)) throw std::invalid_argument(edge_name(e) + ": a wing lies on the edge");
      hinge.w[2 + k] = 1 / h;
      along += s / h;
    }
    hinge.w[1] = -along / length;
    hinge.w[0] = -hinge.w[1] - hinge.w[2] - hinge.w[3];
    // |sum w x| at rest is 2 sin(theta / 2) of the rest dihedral angle theta.
    Vec3 rest = Vec3::Zero();
    for (int p = 0; p < 4; ++p)
      rest += hinge.w[p] * mesh.vertices[hinge.v[p]];
    if (rest.norm() > Real(1e-6))
      throw std::invalid_argument(edge_name(e) + " is not flat at rest (dihedral angle " +
                                  std::to_string(rest.norm()) + " rad)");
    const Real area = triangle_area(mesh, e.faces[0]) + triangle_area(mesh, e.faces[1]);
    hinge.stiffness = bending_stiffness * length * length / area;  // (unit: N m)
    hinges.push_back(hinge);
  }
  return hinges;
}

std::vector<Real> membrane_masses(const geometry::TriangleMesh& mesh,
                                  const StiffeningMembrane& material) {
  std::vector<Real> mass(mesh.vertices.size(), Real(0));
  for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f) {
    const Real share = material.density * material.thickness * triangle_area(mesh, f) / 3;
    for (std::uint32_t v : mesh.triangles[f])
      mass[v] += share;
  }
  return mass;
}

}  // namespace imasim::physics
