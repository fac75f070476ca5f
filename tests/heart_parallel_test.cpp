// The heart's searches on several threads (tissue/heart_field.hpp, tissue/surface_contacts.hpp):
// each particle's answer is its own, so two threads must give the rows, the order and the put-out
// positions of one, bit for bit. And the grid the searches walk, rebuilt only once the heart has
// travelled its slack, must still find what a scan of every triangle finds.
#include <gtest/gtest.h>

#include <limits>
#include <random>
#include <vector>

#include "geometry/closest_point.hpp"
#include "physics/executor.hpp"
#include "tissue/heart.hpp"
#include "tissue/heart_field.hpp"
#include "tissue/surface_contacts.hpp"
#include "tissue/tissue_world.hpp"

namespace imasim::tissue {
namespace {

constexpr double kDt = 0.005;  // the physics step (unit: s)

// Particles scattered within -3 ... +3 mm of the heart's surface, some fixed, moving.
physics::Particles particles_near(const HeartField& heart, std::size_t count) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<Real> unit(-1, 1);
  physics::Particles P;
  for (std::size_t k = 0; k < count; ++k) {
    const std::size_t v = (k * 7919) % heart.current.size();
    const Vec3 x = heart.current[v] + Real(0.003) * unit(rng) * heart.normals[v] +
                   Real(0.001) * Vec3(unit(rng), unit(rng), unit(rng));
    P.add(x, Real(1e-4), 0);
    if (k % 17 == 0) P.inverse_mass.back() = 0;  // fixed: not searched
    P.velocity.back() = Real(0.02) * Vec3(unit(rng), unit(rng), unit(rng));
  }
  return P;
}

TEST(HeartParallel, TwoThreadsGatherThePlanesOfOneInTheSameOrder) {
  const HeartModel model = make_procedural_heart(HeartParams{});
  HeartField one = make_heart_field(model, HeartPlayback{});
  TissueWorld world;
  advance_heart(one, world, kDt);
  HeartField two = one;
  const physics::Particles P = particles_near(one, 3000);
  const physics::Executor serial(1), pair(2);
  std::size_t rows = 0;
  for (int step = 0; step < 3; ++step) {  // the second and third with the clearance filled
    physics::ContactSet a, b;
    gather_heart_contacts(one, P, Real(kDt), SurfaceContactParams{}, a, serial);
    gather_heart_contacts(two, P, Real(kDt), SurfaceContactParams{}, b, pair);
    ASSERT_EQ(a.rows.size(), b.rows.size());
    for (std::size_t k = 0; k < a.rows.size(); ++k) {
      ASSERT_EQ(a.rows[k].particle, b.rows[k].particle) << k;
      ASSERT_EQ(a.rows[k].point0, b.rows[k].point0) << k;
      ASSERT_EQ(a.rows[k].point1, b.rows[k].point1) << k;
      ASSERT_EQ(a.rows[k].normal, b.rows[k].normal) << k;
    }
    for (std::size_t k = 1; k < a.rows.size(); ++k)
      ASSERT_LE(a.rows[k - 1].particle, a.rows[k].particle);  // in the particles' order
    rows += a.rows.size();
    EXPECT_EQ(one.clearance.searched, two.clearance.searched);
    EXPECT_EQ(one.clearance.skipped, two.clearance.skipped);
  }
  EXPECT_GT(rows, 3000u);  // most particles lie within reach, many of both ventricles
}

TEST(HeartParallel, TwoThreadsPutTheParticlesOutWhereOneDoes) {
  const HeartModel model = make_procedural_heart(HeartParams{});
  HeartField one = make_heart_field(model, HeartPlayback{});
  TissueWorld world;
  HeartField two = one;
  physics::Particles a = particles_near(one, 3000), b = a;
  const std::vector<Vec3> start = a.position;
  const physics::Executor serial(1), pair(2);
  const std::uint32_t out_one = collide_with_heart(one, a, start, serial);
  const std::uint32_t out_two = collide_with_heart(two, b, start, pair);
  EXPECT_EQ(out_one, out_two);
  EXPECT_GT(out_one, 500u);  // about half started inside
  EXPECT_EQ(two.last_contacts, out_two);
  for (std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a.position[i], b.position[i]) << i;
    ASSERT_EQ(a.velocity[i], b.velocity[i]) << i;
  }
  EXPECT_EQ(one.clearance.searched, two.clearance.searched);
}

// The nearest point of each ventricle within `search`, by a scan of every triangle.
std::vector<HeartField::Nearest> scan(const HeartField& h, const Vec3& p, Real search) {
  std::vector<HeartField::Nearest> best(h.nearest.size());
  const auto& tris = h.model.topology.triangles;
  for (std::uint32_t t = 0; t < tris.size(); ++t) {
    const geometry::TrianglePoint q = geometry::closest_point_on_triangle(
        p, h.current[tris[t][0]], h.current[tris[t][1]], h.current[tris[t][2]]);
    HeartField::Nearest& b = best[h.triangle_component[t]];
    if (q.distance2 <= search * search && q.distance2 < b.distance2) {
      b.distance2 = q.distance2;
      b.triangle = t;
    }
  }
  return best;
}

TEST(HeartParallel, TheGridKeptOverItsSlackFindsWhatAScanFinds) {
  const HeartModel model = make_procedural_heart(HeartParams{});
  HeartField heart = make_heart_field(model, HeartPlayback{});
  TissueWorld world;
  std::mt19937 rng(3);
  std::uniform_real_distribution<Real> unit(-1, 1);
  std::size_t found = 0, mismatches = 0, kept = 0;
  Real built_at = heart.grid_travel_at;
  for (int step = 1; step <= 200; ++step) {  // a beat and a half
    advance_heart(heart, world, step * kDt);
    kept += heart.grid_travel_at == built_at ? 1 : 0;
    built_at = heart.grid_travel_at;
    // What the answers rest on: each triangle lies inside the box it is filed under.
    for (std::size_t t = 0; t < heart.boxes.size(); ++t)
      ASSERT_TRUE(heart.grid_boxes[t].contains(heart.boxes[t])) << "step " << step << ", " << t;
    for (int k = 0; k < 40; ++k) {
      const std::size_t v = static_cast<std::size_t>(rng()) % heart.current.size();
      const Vec3 p = heart.current[v] + Real(0.002) * Vec3(unit(rng), unit(rng), unit(rng));
      const Real search = Real(0.0015);
      nearest_per_component(heart, p, search);
      const std::vector<HeartField::Nearest> expected = scan(heart, p, search);
      for (std::size_t c = 0; c < expected.size(); ++c) {
        found += expected[c].triangle != HeartField::kNone ? 1 : 0;
        // The same distance (a tie may name another triangle).
        const bool same = heart.nearest[c].triangle == HeartField::kNone
                              ? expected[c].triangle == HeartField::kNone
                              : expected[c].triangle != HeartField::kNone &&
                                    heart.nearest[c].distance2 == expected[c].distance2;
        mismatches += same ? 0 : 1;
      }
    }
  }
  EXPECT_EQ(mismatches, 0u);
  EXPECT_GT(found, 4000u);
  EXPECT_GT(kept, 100u);  // most steps searched a grid built steps before
  EXPECT_LT(kept, 200u);  // and it was rebuilt as the heart moved
}

}  // namespace
}  // namespace imasim::tissue
