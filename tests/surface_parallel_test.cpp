// The step's other per-particle and per-mesh passes on two threads (tissue/surface_contacts.hpp,
// tissue/tissue_step.hpp): the chest wall's and the cavity floor's rows are gathered over fixed
// chunks of the particles, and the meshes' normals and visual meshes are refreshed with the
// heaviest mesh beside the rest. Each must give what one pass on one thread gives, bit for bit
// and in the same order: the solve's results depend on the rows' order.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "physics/executor.hpp"
#include "tissue/surface_contacts.hpp"
#include "tissue/thoracic_patch.hpp"
#include "tissue/tissue_step.hpp"

namespace imasim::tissue {
namespace {

constexpr Real kDt = Real(0.005);  // the physics step (unit: s)

TEST(SurfaceParallel, TwoThreadsGatherTheWallsAndTheFloorsRowsOfOneInOrder) {
  geometry::CylinderPatchSpec wall;  // radius 0.1 m about the z axis
  const Real floor_y = Real(-0.05);
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> unit(-1, 1);
  physics::Particles P;
  for (int k = 0; k < 5000; ++k) {
    Vec3 x;
    if (k % 2 == 0) {  // within 4 mm of the wall, either side of its reach
      const Real a = Real(0.5) * unit(rng), r = wall.radius + Real(0.004) * unit(rng);
      x = Vec3(r * std::sin(a), r * std::cos(a), Real(0.07) * unit(rng));
    } else {  // within 4 mm of the floor
      x = Vec3(Real(0.05) * unit(rng), floor_y + Real(0.004) * unit(rng), Real(0.07) * unit(rng));
    }
    P.add(x, Real(1e-4), 0);
    if (k % 13 == 0) P.inverse_mass.back() = 0;  // fixed: no row
    P.velocity.back() = Real(0.05) * Vec3(unit(rng), unit(rng), unit(rng));
  }
  physics::ContactSet one, two;
  gather_wall_contacts(wall, P, kDt, SurfaceContactParams{}, one);
  gather_floor_contacts(floor_y, P, kDt, SurfaceContactParams{}, one);
  const physics::Executor pair(2);
  WallAndFloorChunks chunks;
  for (int step = 0; step < 2; ++step) {  // the second with the chunks' room kept
    two.clear();
    gather_wall_and_floor_contacts(wall, floor_y, P, kDt, SurfaceContactParams{}, two, pair,
                                   chunks);
    ASSERT_EQ(one.rows.size(), two.rows.size());
    for (std::size_t k = 0; k < one.rows.size(); ++k) {
      ASSERT_EQ(one.rows[k].particle, two.rows[k].particle) << k;
      ASSERT_EQ(one.rows[k].tag, two.rows[k].tag) << k;
      ASSERT_EQ(one.rows[k].point0, two.rows[k].point0) << k;
      ASSERT_EQ(one.rows[k].point1, two.rows[k].point1) << k;
      ASSERT_EQ(one.rows[k].normal, two.rows[k].normal) << k;
      ASSERT_EQ(one.rows[k].static_friction, two.rows[k].static_friction) << k;
    }
  }
  // Both surfaces found rows, the wall's all before the floor's, and no fixed particle has one.
  std::size_t walls = 0, floors = 0;
  for (const physics::ContactRow& c : one.rows) {
    EXPECT_NE(P.inverse_mass[c.particle], 0);
    if (c.tag == kWallContact) {
      EXPECT_EQ(floors, 0u);
      ++walls;
    } else {
      EXPECT_EQ(c.tag, kFloorContact);
      ++floors;
    }
  }
  EXPECT_GT(walls, 1000u);
  EXPECT_GT(floors, 1000u);
}

TEST(SurfaceParallel, TwoThreadsRefreshTheNormalsAndVisualMeshesAsOne) {
  ThoracicPatch patch = make_thoracic_patch(default_thoracic_patch_params());
  finish_setup(patch.world);
  ASSERT_FALSE(patch.world.visuals.empty());
  // Every particle moved at random, so that every normal and bound vertex changes.
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> unit(-1, 1);
  for (Vec3& x : patch.world.state.particles.position)
    x += Real(0.001) * Vec3(unit(rng), unit(rng), unit(rng));
  TissueWorld one = patch.world, two = patch.world;
  const physics::Executor pair(2);
  update_surfaces(one);
  update_surfaces(two, pair);
  for (std::size_t m = 0; m < one.meshes.size(); ++m) {
    ASSERT_EQ(one.meshes[m].normals.size(), two.meshes[m].normals.size());
    for (std::size_t v = 0; v < one.meshes[m].normals.size(); ++v)
      ASSERT_EQ(one.meshes[m].normals[v], two.meshes[m].normals[v]) << m << " " << v;
  }
  std::size_t moved = 0;
  for (std::size_t k = 0; k < one.visuals.size(); ++k) {
    ASSERT_EQ(one.visuals[k].positions.size(), two.visuals[k].positions.size());
    for (std::size_t v = 0; v < one.visuals[k].positions.size(); ++v) {
      ASSERT_EQ(one.visuals[k].positions[v], two.visuals[k].positions[v]) << k << " " << v;
      moved += one.visuals[k].positions[v] != patch.world.visuals[k].positions[v] ? 1 : 0;
    }
  }
  EXPECT_GT(moved, 100u);  // the refresh did something to compare
}

}  // namespace
}  // namespace imasim::tissue
