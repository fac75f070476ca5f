// XSPH velocity smoothing of the fat (SPEC S2): a common motion is left alone, a particle moving
// against its neighbours is pulled towards their kernel-weighted mean by the coefficient c.
#include <gtest/gtest.h>

#include "precision.hpp"
#include "tissue/strands.hpp"
#include "tissue/thoracic_patch.hpp"
#include "tissue/xsph.hpp"

namespace imasim::tissue {
namespace {

TEST(Xsph, LeavesACommonVelocityAlone) {
  ThoracicPatch patch = make_thoracic_patch(default_thoracic_patch_params());
  TissueWorld& w = patch.world;
  for (Vec3& v : w.state.particles.velocity)
    v = Vec3(0.01, -0.02, 0.005);
  smooth_strand_velocities(w);
  for (const Vec3& v : w.state.particles.velocity) {
    EXPECT_LT((v - Vec3(0.01, -0.02, 0.005)).norm(), test::ulps(8, 0.03));
  }
}

TEST(Xsph, PullsAnOutlierTowardsItsNeighboursMean) {
  ThoracicPatch patch = make_thoracic_patch(default_thoracic_patch_params());
  TissueWorld& w = patch.world;
  const StrandSet& set = w.strands[patch.fascia_fat];
  for (Vec3& v : w.state.particles.velocity)
    v.setZero();
  // The interior particle with the most neighbours moves at 1 cm/s along x.
  std::uint32_t k_best = 0, most = 0;
  for (std::uint32_t k = 0; k < set.particle_count(); ++k) {
    const std::uint32_t n = set.neighbour_start[k + 1] - set.neighbour_start[k];
    if (n > most) most = n, k_best = k;
  }
  ASSERT_GT(most, 2u);
  const std::uint32_t i = set.first_particle + k_best;
  w.state.particles.velocity[i] = Vec3(0.01, 0, 0);
  smooth_strand_velocities(w);
  // Its neighbours are at rest: v_i' = v_i + c (0 - v_i) = (1 - c) v_i.
  EXPECT_NEAR(w.state.particles.velocity[i].x(), (1 - set.xsph_coefficient) * 0.01, 1e-15);
  // Each neighbour within h gains a share of it, never more than c v_i.
  int moved = 0;
  for (std::uint32_t n = set.neighbour_start[k_best]; n < set.neighbour_start[k_best + 1]; ++n) {
    const double vx = w.state.particles.velocity[set.first_particle + set.neighbours[n]].x();
    EXPECT_GE(vx, 0.0);
    EXPECT_LE(vx, set.xsph_coefficient * 0.01 + 1e-15);
    moved += vx > 0 ? 1 : 0;
  }
  EXPECT_GT(moved, 0);
}

TEST(TissueWorld, EachObjectKeepsItsOwnParameters) {
  const ThoracicPatch patch = make_thoracic_patch(default_thoracic_patch_params());
  const TissueWorld& w = patch.world;
  const auto& objects = w.model.objects;
  EXPECT_EQ(objects[w.meshes[patch.ima].object].gravity, Vec3::Zero());  // 2.3.2
  EXPECT_NE(objects[w.meshes[patch.fascia].object].gravity, Vec3::Zero());
  EXPECT_DOUBLE_EQ(objects[w.meshes[patch.fascia].object].linear_damping, 0.03);
  EXPECT_DOUBLE_EQ(objects[w.meshes[patch.fascia].object].angular_damping, 0.01);
  // Uniform mass per object (eq. 5): 6 g over the fascia's 480 vertices.
  const MeshObject& f = w.meshes[patch.fascia];
  const std::uint32_t inner = f.first_particle + 12 + 1;  // not on the fixed perimeter
  EXPECT_NEAR(1 / w.state.particles.inverse_mass[inner], 0.006 / 480, 1e-15);
  for (std::uint32_t k = 0; k < w.meshes[patch.wall].particle_count; ++k) {
    EXPECT_TRUE(w.state.particles.is_fixed(w.meshes[patch.wall].first_particle + k));
  }
}

TEST(TissueWorld, RejectsBadTissueParameters) {
  ThoracicPatchParams p = default_thoracic_patch_params();
  p.fascia_fat.xsph_coefficient = 2;
  EXPECT_THROW(make_thoracic_patch(p), std::invalid_argument);
  p = default_thoracic_patch_params();
  p.vessel.object.total_mass = 0;
  EXPECT_THROW(make_thoracic_patch(p), std::invalid_argument);
  p = default_thoracic_patch_params();
  p.ima_fat.generation.segments = 0;
  EXPECT_THROW(make_thoracic_patch(p), std::invalid_argument);
  TissueWorld w;
  geometry::TriangleMesh non_manifold;
  non_manifold.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0),
                           Vec3(0, 0, 1)};
  non_manifold.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  MeshObjectParams params;
  params.name = "bad";
  EXPECT_THROW(add_mesh_object(w, non_manifold, params), std::invalid_argument);
  EXPECT_EQ(w.state.particles.size(), 0u);  // refused before anything was added
  EXPECT_TRUE(w.model.objects.empty());
}

}  // namespace
}  // namespace imasim::tissue
