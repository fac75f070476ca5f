#include "tissue/tissue_step.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "geometry/vertex_normals.hpp"
#include "math/stopwatch.hpp"
#include "physics/validation.hpp"
#include "tissue/fat_support.hpp"
#include "tissue/mesh_object.hpp"
#include "tissue/strands.hpp"
#include "tissue/xsph.hpp"

namespace imasim::tissue {

namespace {

// One mesh's normals, then the visual meshes bound to it.
void update_mesh_surfaces(TissueWorld& world, std::uint32_t mesh) {
  MeshObject& m = world.meshes[mesh];
  geometry::compute_vertex_normals(mesh_positions(world, m), m.triangles, m.normals);
  for (VisualMesh& v : world.visuals) {
    if (v.source_mesh != mesh) continue;
    geometry::apply_bindings(v.bindings, mesh_positions(world, m), m.normals, m.triangles,
                             v.positions);
  }
}

}  // namespace

void update_surfaces(TissueWorld& world, const physics::Executor& exec) {
  // Two parts side by side: the mesh with the most vertices, its visual meshes' counted, and the
  // rest. The meshes share nothing, so each result is the same bits as in one pass.
  const auto meshes = static_cast<std::uint32_t>(world.meshes.size());
  std::uint32_t heaviest = 0;
  std::size_t most = 0;
  for (std::uint32_t m = 0; m < meshes; ++m) {
    std::size_t vertices = world.meshes[m].particle_count;
    for (const VisualMesh& v : world.visuals)
      if (v.source_mesh == m) vertices += v.positions.size();
    if (vertices > most) most = vertices, heaviest = m;
  }
  exec.run_side_by_side(
      [&] {
        if (heaviest < meshes) update_mesh_surfaces(world, heaviest);
      },
      [&] {
        for (std::uint32_t m = 0; m < meshes; ++m)
          if (m != heaviest) update_mesh_surfaces(world, m);
      });
}

void update_surfaces(TissueWorld& world) {
  const physics::Executor serial(1);
  update_surfaces(world, serial);
}

void finish_setup(TissueWorld& world) {
  // Every scene is checked once when it is made (MuJoCo's and Box2D's habit): a bad model or an
  // inconsistent state is refused here, not found by the first step.
  if (const std::string error = physics::validate_model(world.model); !error.empty()) {
    throw std::invalid_argument("tissue world: " + error);
  }
  physics::prepare_state(world.model, world.state);
  if (const std::string error = physics::validate_state(world.model, world.state); !error.empty()) {
    throw std::invalid_argument("tissue world: " + error);
  }
  world.xsph_scratch.resize(world.state.particles.size());
  world.xsph_weight.resize(world.state.particles.size());
  world.reference = world.state.particles.rest_position;
  world.held.resize(world.state.particles.size(), 0);
  world.manipulated.resize(world.state.particles.size(), 0);
  // Contacts are gathered every step: room for two per particle, so stepping does not allocate.
  world.state.contacts.rows.reserve(2 * world.state.particles.size());
  world.state.supports.reserve(2 * world.state.particles.size());
  world.support_stiffness.assign(world.state.particles.size(), 0);
  world.support_direction.assign(world.state.particles.size(), Vec3::Zero());
  std::size_t pairs = 0;
  for (const OffsetCoupling& c : world.couplings)
    pairs += c.pairs.size();
  world.state.follows.reserve(pairs);
  update_surfaces(world);
  place_strand_ends(world);
}

void mark_manipulated(TissueWorld& world) {
  std::fill(world.manipulated.begin(), world.manipulated.end(), std::uint8_t(0));
  for (const StrandSet& set : world.strands) {
    const std::uint32_t n = set.segments + 1;
    for (std::uint32_t s = 0; s < set.strand_count; ++s) {
      const std::uint32_t first = set.particle(s, 0);
      bool held = false;
      for (std::uint32_t k = 0; k < n && !held; ++k)
        held = first + k < world.held.size() && world.held[first + k];
      if (!held) continue;
      for (std::uint32_t k = 0; k < n; ++k)
        if (first + k < world.manipulated.size()) world.manipulated[first + k] = 1;
    }
  }
}

physics::StepResult step_tissue_dynamics(TissueWorld& world, physics::Executor& exec) {
  Stopwatch clock;
  mark_manipulated(world);
  const CouplingFlags flags{world.held, world.manipulated};
  // The pairs that follow their source (eq. 8, eq. 9 with beta = 1) act inside the solve.
  world.state.follows.clear();
  for (const OffsetCoupling& c : world.couplings)
    append_follow_rows(c, world.state.particles, world.reference, flags, world.state.follows);
  gather_fat_supports(world);
  const double follow_rows = clock.lap();
  physics::StepResult r = physics::step(world.model, world.state, exec);
  clock.lap();
  r.profile[physics::Stage::coupling] += follow_rows;
  if (!r.ok()) return r;
  smooth_strand_velocities(world, exec);
  // eq. 9 with beta = 0: the decay after the step, with the velocity made to agree.
  for (const OffsetCoupling& c : world.couplings) {
    apply_coupling(c, world.state.particles, world.reference, world.state.scratch.saved_position,
                   world.model.solver.dt, flags, PairsApplied::relaxing);
  }
  r.profile[physics::Stage::coupling] += clock.lap();
  return r;
}

void finish_tissue_step(TissueWorld& world, const physics::Executor& exec) {
  update_surfaces(world, exec);
  place_strand_ends(world);
}

void finish_tissue_step(TissueWorld& world) {
  const physics::Executor serial(1);
  finish_tissue_step(world, serial);
}

physics::StepResult step_tissue(TissueWorld& world, physics::Executor& exec) {
  physics::StepResult r = step_tissue_dynamics(world, exec);
  if (!r.ok()) return r;
  Stopwatch clock;
  finish_tissue_step(world, exec);
  r.profile[physics::Stage::surfaces] += clock.lap();
  return r;
}

}  // namespace imasim::tissue
