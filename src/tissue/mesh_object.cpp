#include "tissue/mesh_object.hpp"

#include <stdexcept>

#include "geometry/edge_adjacency.hpp"
#include "geometry/grid_rectangle.hpp"
#include "geometry/vertex_normals.hpp"
#include "physics/mesh_constraints.hpp"
#include "tissue/topology_change.hpp"

namespace imasim::tissue {

physics::ObjectId add_object(physics::Model& model, const std::string& name, bool gravity,
                             Real linear_damping, Real angular_damping) {
  physics::ObjectParams o;
  o.name = name;
  if (!gravity) o.gravity.setZero();
  o.linear_damping = linear_damping;
  o.angular_damping = angular_damping;
  model.objects.push_back(o);
  return static_cast<physics::ObjectId>(model.objects.size() - 1);
}

std::uint32_t add_mesh_object(TissueWorld& world, const geometry::TriangleMesh& mesh,
                              const MeshObjectParams& p) {
  if (mesh.vertices.empty()) throw std::invalid_argument(p.name + ": empty mesh");
  if (!(p.total_mass > 0)) throw std::invalid_argument(p.name + ": total_mass must be > 0");
  // Checked before anything is added, so a refused mesh leaves the world as it was.
  const geometry::EdgeAdjacency adjacency = geometry::build_edge_adjacency(mesh);
  if (!adjacency.non_manifold_edges.empty()) {
    const auto& e = adjacency.non_manifold_edges.front();
    throw std::invalid_argument(p.name + ": mesh is not a manifold: edge " + std::to_string(e[0]) +
                                "-" + std::to_string(e[1]) + " is shared by more than two faces");
  }
  MeshObject m;
  m.name = p.name;
  m.object = add_object(world.model, p.name, p.gravity, p.linear_damping, p.angular_damping);
  physics::Particles& P = world.state.particles;
  m.first_particle = static_cast<std::uint32_t>(P.size());
  m.particle_count = static_cast<std::uint32_t>(mesh.vertices.size());
  const Real vertex_mass = p.total_mass / Real(mesh.vertices.size());  // eq. 5
  for (const Vec3& x : mesh.vertices) {
    const std::uint32_t i = P.add(x, vertex_mass, m.object);
    if (p.is_static) P.fix(i);
  }
  if (!p.is_static) {
    const physics::MaterialId stretch = world.model.add_material(p.stretch);
    const physics::MaterialId bend = world.model.add_material(p.bend);
    physics::add_mesh_constraints(world.state.constraints, P, adjacency, m.first_particle, stretch,
                                  bend);
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

FasciaParams default_fascia_params() {
  FasciaParams f;
  f.object.name = "fascia";
  f.object.total_mass = Real(0.006);      // 40 x 150 mm, ~1 mm thick, ~1000 kg/m^3
  f.object.linear_damping = Real(0.03);   // 2.3.1
  f.object.angular_damping = Real(0.01);  // 2.3.1
  f.object.stretch = physics::ConstraintMaterial::xpbd(Real(1e-4));  // (m/N)
  f.object.bend = physics::ConstraintMaterial::xpbd(Real(10));       // (rad/(N m))
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
