#include "tissue/mesh_object.hpp"

#include <algorithm>
#include <stdexcept>

#include "geometry/edge_adjacency.hpp"
#include "geometry/grid_rectangle.hpp"
#include "geometry/vertex_normals.hpp"
#include "physics/mesh_constraints.hpp"
#include "tissue/topology_change.hpp"

namespace imasim::tissue {

physics::ObjectId add_object(TissueWorld& world, const std::string& name, bool gravity,
                             Real linear_damping, Real angular_damping, bool coarse) {
  physics::ObjectParams o;
  o.name = name;
  if (!gravity) o.gravity.setZero();
  o.linear_damping = linear_damping;
  o.angular_damping = angular_damping;
  o.coarse = coarse;
  world.model.objects.push_back(o);
  const auto id = static_cast<physics::ObjectId>(world.model.objects.size() - 1);
  world.state.constraints.set_object_band(id, coarse);
  return id;
}

std::uint32_t add_mesh_object(TissueWorld& world, const geometry::TriangleMesh& mesh,
                              const MeshObjectParams& p) {
  if (mesh.vertices.empty()) throw std::invalid_argument(p.name + ": empty mesh");
  if (!(p.total_mass > 0)) throw std::invalid_argument(p.name + ": total_mass must be > 0");
  if (p.membrane) p.membrane->validate(p.name.c_str());
  // Checked before anything is added, so a refused mesh leaves the world as it was.
  const geometry::EdgeAdjacency adjacency = geometry::build_edge_adjacency(mesh);
  if (!adjacency.non_manifold_edges.empty()) {
    const auto& e = adjacency.non_manifold_edges.front();
    throw std::invalid_argument(p.name + ": mesh is not a manifold: edge " + std::to_string(e[0]) +
                                "-" + std::to_string(e[1]) + " is shared by more than two faces");
  }
  MeshObject m;
  m.name = p.name;
  m.object = add_object(world, p.name, p.gravity, p.linear_damping, p.angular_damping, p.coarse);
  physics::Particles& P = world.state.particles;
  m.first_particle = static_cast<std::uint32_t>(P.size());
  m.particle_count = static_cast<std::uint32_t>(mesh.vertices.size());
  const Real vertex_mass = p.total_mass / Real(mesh.vertices.size());  // eq. 5
  for (const Vec3& x : mesh.vertices) {
    const std::uint32_t i = P.add(x, vertex_mass, m.object);
    if (p.is_static) P.fix(i);
  }
  if (!p.is_static) {
    const physics::MaterialId stretch =
        world.model.add_material(p.membrane ? p.membrane->stretch() : p.stretch);
    const physics::MaterialId bend =
        world.model.add_material(p.membrane ? p.membrane->bend() : p.bend);
    m.per_row =
        p.membrane ? physics::CompliancePerRow::membrane : physics::CompliancePerRow::material;
    physics::add_mesh_constraints(world.state.constraints, P, mesh, adjacency, m.first_particle,
                                  stretch, bend, m.per_row);
    m.stretch_material = stretch;
    m.bend_material = bend;
  }
  m.total_mass = p.total_mass;
  m.particle_capacity = m.particle_count + p.spare_vertices;
  for (std::uint32_t k = 0; k < p.spare_vertices; ++k) {
    P.fix(P.add(mesh.vertices.front(), vertex_mass, m.object));  // parked until cutting uses it
  }
  m.triangles = mesh.triangles;
  m.normals.resize(mesh.vertices.size());
  geometry::compute_vertex_normals(mesh.vertices, mesh.triangles, m.normals);
  world.meshes.push_back(std::move(m));
  const auto index = static_cast<std::uint32_t>(world.meshes.size() - 1);
  if (p.spare_vertices > 0 && !p.is_static) index_mesh_edges(world, index);
  return index;
}

double max_displacement(const TissueWorld& w, const MeshObject& m) {
  double largest = 0;
  const physics::Particles& P = w.state.particles;
  for (std::uint32_t k = 0; k < m.particle_count; ++k) {
    const std::uint32_t i = m.first_particle + k;
    largest = std::max(largest, double((P.position[i] - P.rest_position[i]).norm()));
  }
  return largest;
}

physics::MembraneMaterial default_fascia_membrane() {
  physics::MembraneMaterial m;
  // Small-strain (toe-region) modulus of a fascial membrane: its linear region is stiffer (2.65
  // MPa, superficial fascia) but sagging and gentle handling strain it by well under the toe's
  // few per cent (docs/tissue.md). 1 mm thick. D from plate theory.
  m.youngs_modulus = Real(1e5);
  m.thickness = Real(0.001);
  return m;
}

FasciaParams default_fascia_params() {
  FasciaParams f;
  f.object.name = "fascia";
  f.object.total_mass = Real(0.006);      // 40 x 150 mm, ~1 mm thick, ~1000 kg/m^3
  f.object.linear_damping = Real(0.03);   // 2.3.1, per 5 ms
  f.object.angular_damping = Real(0.01);  // 2.3.1, per 5 ms
  f.object.membrane = default_fascia_membrane();
  f.object.spare_vertices = 2048;  // room for the vertices a harvest's cuts add
  return f;
}

std::uint32_t add_fascia(TissueWorld& world, const FasciaParams& p) {
  geometry::TriangleMesh mesh = geometry::make_grid_rectangle({p.width, p.height, p.nx, p.ny});
  for (Vec3& x : mesh.vertices)
    x = p.pose.apply(x);
  const std::uint32_t index = add_mesh_object(world, mesh, p.object);
  const MeshObject& m = world.meshes[index];
  for (std::uint32_t j = 0; j < p.ny; ++j) {
    for (std::uint32_t i = 0; i < p.nx; ++i) {
      if (i == 0 || j == 0 || i + 1 == p.nx || j + 1 == p.ny) {
        world.state.particles.fix(m.first_particle + geometry::grid_index(i, j, p.nx));
      }
    }
  }
  return index;
}

}  // namespace imasim::tissue
