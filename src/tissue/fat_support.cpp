#include "tissue/fat_support.hpp"

namespace imasim::tissue {

namespace {

// A row for particle i if it is dynamic and, for a column that pushes only, within reach of its
// plane.
void add_support(TissueWorld& w, std::uint32_t i, const Vec3& direction, Real stiffness,
                 bool pushes_only) {
  const physics::Particles& P = w.state.particles;
  if (!(stiffness > 0) || P.inverse_mass[i] == 0) return;
  const Real offset = direction.dot(w.reference[i]);
  const Real gap = direction.dot(P.position[i]) - offset;
  const Real reach = kSupportReach + 2 * P.velocity[i].norm() * w.model.solver.dt;
  if (pushes_only && gap > reach) return;
  w.state.supports.push_back({i, direction, offset, 1 / stiffness, 0, 0, pushes_only});
}

}  // namespace

void gather_fat_supports(TissueWorld& w) {
  w.state.supports.clear();
  const physics::Particles& P = w.state.particles;
  for (const StrandSet& set : w.strands) {
    if (set.column_stiffness.empty()) continue;
    const MeshObject& held = w.meshes[set.mesh_a];
    for (std::uint32_t s = 0; s < set.strand_count; ++s) {
      if (set.cut[s] != kStrandIntact) continue;
      const Real k = set.column_stiffness[s];  // (unit: N/m)
      const Vec3& d = set.column_direction[s];
      const Vec3& base = P.rest_position[set.particle(s, set.segments)];
      const Real length = d.dot(P.rest_position[set.particle(s, 0)] - base);
      for (std::uint32_t j = 1; j < set.segments; ++j) {
        const std::uint32_t i = set.particle(s, j);
        const Real height = d.dot(P.rest_position[i] - base);
        if (height > 0) add_support(w, i, d, k * length / height, true);  // the column below
      }
      const geometry::SurfaceBinding& end = set.end_a[s];
      const geometry::Triangle& face = held.triangles[end.triangle];
      for (std::uint32_t c = 0; c < 3; ++c) {
        const std::uint32_t i = held.first_particle + face[c];
        w.support_stiffness[i] += end.bary[c] * k;
        w.support_direction[i] += (end.bary[c] * k) * d;
      }
    }
    // The held surface's vertices, in order; the sums are cleared for the next set.
    for (std::uint32_t v = 0; v < held.particle_count; ++v) {
      const std::uint32_t i = held.first_particle + v;
      const Real k = w.support_stiffness[i];
      if (k > 0) {
        const Real size = w.support_direction[i].norm();
        if (size > 0) {
          // Along the columns k, across them kAcrossColumns k, both ways: three rows on
          // orthonormal directions make the layer's hold a spring in every direction.
          const Vec3 along = w.support_direction[i] / size;
          const Vec3 across = along.unitOrthogonal();
          add_support(w, i, along, k, false);
          add_support(w, i, across, kAcrossColumns * k, false);
          add_support(w, i, along.cross(across), kAcrossColumns * k, false);
        }
      }
      w.support_stiffness[i] = 0;
      w.support_direction[i] = Vec3::Zero();
    }
  }
}

}  // namespace imasim::tissue
