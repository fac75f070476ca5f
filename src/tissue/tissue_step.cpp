#include "tissue/tissue_step.hpp"

#include "geometry/vertex_normals.hpp"
#include "tissue/mesh_object.hpp"
#include "tissue/strands.hpp"
#include "tissue/xsph.hpp"

namespace imasim::tissue {

void update_surfaces(TissueWorld& world) {
  for (MeshObject& m : world.meshes) {
    geometry::compute_vertex_normals(mesh_positions(world, m), m.triangles, m.normals);
  }
  for (VisualMesh& v : world.visuals) {
    const MeshObject& m = world.meshes[v.source_mesh];
    geometry::apply_bindings(v.bindings, mesh_positions(world, m), m.normals, m.triangles,
                             v.positions);
  }
}

void finish_setup(TissueWorld& world) {
  physics::prepare_state(world.model, world.state);
  world.xsph_scratch.resize(world.state.particles.size());
  world.reference = world.state.particles.rest_position;
  update_surfaces(world);
  place_strand_ends(world);
}

physics::StepResult step_tissue_dynamics(TissueWorld& world, physics::Executor& exec) {
  const physics::StepResult r = physics::step(world.model, world.state, exec);
  if (!r.ok()) return r;
  smooth_strand_velocities(world);
  for (const OffsetCoupling& c : world.couplings) {
    apply_coupling(c, world.state.particles, world.reference);
  }
  return r;
}

void finish_tissue_step(TissueWorld& world) {
  update_surfaces(world);
  place_strand_ends(world);
}

physics::StepResult step_tissue(TissueWorld& world, physics::Executor& exec) {
  const physics::StepResult r = step_tissue_dynamics(world, exec);
  if (r.ok()) finish_tissue_step(world);
  return r;
}

}  // namespace imasim::tissue
