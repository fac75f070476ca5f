#include "scene/implicit_fascia_scene.hpp"

#include <algorithm>
#include <stdexcept>

#include "scene/thorax_scene.hpp"

namespace imasim::scene {

namespace {

// The fascia's XPBD distance and dihedral rows out of the constraint system, in the edges' order
// (the index is a hash map: sorted for determinism).
void remove_fascia_rows(tissue::TissueWorld& w, tissue::MeshObject& mesh) {
  std::vector<std::uint64_t> keys;
  for (const auto& [key, record] : mesh.edges)
    keys.push_back(key);
  std::sort(keys.begin(), keys.end());
  for (std::uint64_t key : keys) {
    tissue::EdgeRecord& record = mesh.edges[key];
    w.state.constraints.distance.remove(record.distance);
    w.state.constraints.dihedral.remove(record.dihedral);
    record.distance = {};
    record.dihedral = {};
  }
}

void build_fascia_solver(ThoraxScene& scene, SceneImplicitFascia& f) {
  tissue::TissueWorld& w = scene.patch.world;
  f.fascia = tissue::make_implicit_fascia(w, scene.patch.fascia, f.material, f.bending_stiffness,
                                          w.model.solver.dt);
  const tissue::MeshObject& mesh = w.meshes[scene.patch.fascia];
  f.inverse_mass.resize(mesh.particle_count);
  f.velocity.resize(mesh.particle_count);
  f.built_revision = mesh.topology_revision;
}

}  // namespace

void use_implicit_fascia(ThoraxScene& scene, const physics::StiffeningMembrane& material) {
  tissue::TissueWorld& w = scene.patch.world;
  tissue::MeshObject& mesh = w.meshes[scene.patch.fascia];
  const physics::ConstraintMaterial& bend = w.model.materials[mesh.bend_material];
  if (!(bend.compliance > 0))
    throw std::invalid_argument("implicit fascia: the fascia's bending has no stiffness to take");
  SceneImplicitFascia f;
  f.material = material;
  f.bending_stiffness = 1 / bend.compliance;
  build_fascia_solver(scene, f);
  remove_fascia_rows(w, mesh);
  mesh.rows_in_xpbd = false;
  // Sized for the spare vertices cuts bring in, so that a step after a cut allocates nothing.
  f.contacts.reserve(w.state.contacts.rows.capacity());
  f.inverse_mass.reserve(mesh.particle_capacity);
  f.velocity.reserve(mesh.particle_capacity);
  scene.implicit_fascia = std::move(f);
}

void refit_scene_fascia(ThoraxScene& scene) {
  if (!scene.implicit_fascia) return;
  tissue::TissueWorld& w = scene.patch.world;
  remove_fascia_rows(w, w.meshes[scene.patch.fascia]);
  build_fascia_solver(scene, *scene.implicit_fascia);
}

physics::StepResult step_scene_fascia(ThoraxScene& scene) {
  physics::StepResult result;
  if (!scene.implicit_fascia) return result;
  SceneImplicitFascia& f = *scene.implicit_fascia;
  tissue::TissueWorld& w = scene.patch.world;
  const tissue::MeshObject& mesh = w.meshes[scene.patch.fascia];
  if (mesh.topology_revision != f.built_revision) refit_scene_fascia(scene);  // cut since
  const std::uint32_t first = mesh.first_particle, end = first + mesh.particle_count;
  auto on_fascia = [&](const physics::ContactRow& c) {
    return c.particle >= first && c.particle < end;
  };
  f.contacts.clear();
  for (const physics::ContactRow& c : w.state.contacts.rows)
    if (on_fascia(c))
      f.contacts.push_back({c.particle - first, c.point1 + c.margin * c.normal, c.normal});
  std::erase_if(w.state.contacts.rows, on_fascia);
  f.last = tissue::step_implicit_fascia(f.fascia, w, w.model.objects[mesh.object].gravity,
                                        f.contacts, {}, f.solve);
  f.unsolved_steps += f.last.residual > f.solve.tolerance;
  if (!f.last.ok) {
    result.status = physics::StepStatus::non_finite;
    result.particle = first;
  }
  physics::Particles& P = w.state.particles;
  for (std::uint32_t k = 0; k < mesh.particle_count; ++k) {
    f.inverse_mass[k] = P.inverse_mass[first + k];
    f.velocity[k] = P.velocity[first + k];
    P.inverse_mass[first + k] = 0;
  }
  return result;
}

void release_scene_fascia(ThoraxScene& scene) {
  if (!scene.implicit_fascia) return;
  SceneImplicitFascia& f = *scene.implicit_fascia;
  const tissue::MeshObject& mesh = scene.patch.world.meshes[scene.patch.fascia];
  physics::Particles& P = scene.patch.world.state.particles;
  for (std::uint32_t k = 0; k < mesh.particle_count; ++k) {
    P.inverse_mass[mesh.first_particle + k] = f.inverse_mass[k];
    P.velocity[mesh.first_particle + k] = f.velocity[k];
  }
}

}  // namespace imasim::scene
