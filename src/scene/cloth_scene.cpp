#include "scene/cloth_scene.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "geometry/edge_adjacency.hpp"
#include "geometry/grid_rectangle.hpp"
#include "physics/mesh_constraints.hpp"
#include "physics/validation.hpp"
#include "scene/solver_budget.hpp"

namespace imasim::scene {

namespace {

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

}  // namespace

ClothScene make_cloth_scene(const ClothParams& p) {
  require(p.n >= 3 && p.n <= 4096, "cloth: n must be in [3, 4096], got " + std::to_string(p.n));
  require(std::isfinite(p.size) && p.size > 0, "cloth: size must be a positive length in m");
  require(std::isfinite(p.mass) && p.mass > 0, "cloth: mass must be a positive mass in kg");
  const std::string budget = solver_budget_problem(std::uint64_t(p.n) * p.n, p.substeps,
                                                   p.iterations, "substeps x iterations");
  require(budget.empty(), "cloth: " + budget);

  ClothScene scene;
  physics::Model& model = scene.model;
  model.solver.dt = p.dt;
  model.solver.iterations = p.iterations;
  model.solver.substeps = p.substeps;
  model.solver.max_speed = p.max_speed;
  physics::ObjectParams cloth;
  cloth.name = "cloth";
  cloth.linear_damping = p.linear_damping;
  model.objects.push_back(cloth);
  const bool pbd = p.response == physics::Response::pbd;
  const physics::MaterialId stretch =
      model.add_material(pbd ? physics::ConstraintMaterial::pbd(p.pbd_distance_stiffness)
                             : physics::ConstraintMaterial::xpbd(p.distance_compliance));
  const physics::MaterialId bend =
      model.add_material(pbd ? physics::ConstraintMaterial::pbd(p.pbd_bending_stiffness)
                             : physics::ConstraintMaterial::xpbd(p.bending_compliance));
  if (const std::string error = physics::validate_model(model); !error.empty()) {
    throw std::invalid_argument("cloth: " + error);
  }

  scene.mesh = geometry::make_grid_rectangle({p.size, p.size, p.n, p.n});
  physics::Particles& particles = scene.state.particles;
  const Real vertex_mass = p.mass / Real(scene.mesh.vertex_count());  // eq. 5
  for (const Vec3& x : scene.mesh.vertices)
    particles.add(x, vertex_mass, 0);
  for (std::uint32_t j = 0; j < p.n; ++j) {
    for (std::uint32_t i = 0; i < p.n; ++i) {
      if (i == 0 || j == 0 || i == p.n - 1 || j == p.n - 1) {
        particles.fix(geometry::grid_index(i, j, p.n));
      }
    }
  }
  const geometry::EdgeAdjacency adjacency = geometry::build_edge_adjacency(scene.mesh);
  physics::add_mesh_constraints(scene.state.constraints, particles, scene.mesh, adjacency, 0,
                                stretch, bend, physics::CompliancePerRow::material);

  const std::uint32_t lo = (p.n - 1) / 2, hi = p.n / 2;  // equal for odd n
  for (std::uint32_t j = lo; j <= hi; ++j) {
    for (std::uint32_t i = lo; i <= hi; ++i) {
      scene.centre_particles.push_back(geometry::grid_index(i, j, p.n));
    }
  }
  physics::prepare_state(model, scene.state);
  return scene;
}

Real centre_sag(const ClothScene& scene) {
  const physics::Particles& P = scene.state.particles;
  Real sum = 0;
  for (std::uint32_t i : scene.centre_particles)
    sum += P.rest_position[i].y() - P.position[i].y();
  return sum / Real(scene.centre_particles.size());
}

Real max_displacement(const physics::State& state) {
  const physics::Particles& P = state.particles;
  Real max2 = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    max2 = std::max(max2, (P.position[i] - P.rest_position[i]).squaredNorm());
  }
  return std::sqrt(max2);
}

}  // namespace imasim::scene
