// The heart's clearance cache (tissue/heart_clearance.hpp): a particle's query answered from
// what its last search proved must be the full search's answer, whatever the particle and the
// beating heart did since, and the cache must actually spare searches.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "tissue/heart.hpp"
#include "tissue/heart_field.hpp"
#include "tissue/tissue_world.hpp"

namespace imasim::tissue {
namespace {

constexpr double kDt = 0.005;  // the physics step (unit: s)

TEST(HeartClearance, CachedQueriesAnswerAsFullSearchesOfTheBeatingHeart) {
  const HeartModel model = make_procedural_heart(HeartParams{});
  HeartField cached = make_heart_field(model, HeartPlayback{});
  HeartField plain = cached;
  TissueWorld world;  // no anchors: only the heart moves

  // Points on the heart's surface pushed off it by -3...+8 mm along its normal, and points
  // scattered around it, each wandering up to 0.3 mm a step; now and then one jumps elsewhere.
  std::mt19937 rng(7);
  std::uniform_real_distribution<Real> unit(-1, 1);
  std::vector<Vec3> points;
  for (std::size_t v = 0; v < cached.current.size(); v += 5)
    points.push_back(cached.current[v] +
                     Real(0.0055) * (unit(rng) + Real(0.45)) * cached.normals[v]);
  geometry::Box bounds;
  for (const Vec3& x : cached.current)
    bounds.extend(x);
  const Vec3 centre = bounds.center(), half = bounds.sizes() / 2 + Vec3::Constant(Real(0.02));
  for (int k = 0; k < 300; ++k)
    points.push_back(centre + Vec3(unit(rng), unit(rng), unit(rng)).cwiseProduct(half));

  std::size_t found = 0, mismatches = 0;
  for (int step = 1; step <= 400; ++step) {
    advance_heart(cached, world, step * kDt);
    advance_heart(plain, world, step * kDt);
    for (std::size_t i = 0; i < points.size(); ++i) {
      points[i] += Real(0.0003) * Vec3(unit(rng), unit(rng), unit(rng));
      if (step % 50 == 0 && i % 7 == 0) points[i] = points[(i * 13 + step) % points.size()];
      const Real search = kHeartStepSearch + Real(0.0005) * (unit(rng) + 1);
      nearest_per_component_of_particle(cached, static_cast<std::uint32_t>(i), points.size(),
                                        points[i], search);
      nearest_per_component(plain, points[i], search);
      for (std::size_t c = 0; c < plain.nearest.size(); ++c) {
        const HeartField::Nearest &a = cached.nearest[c], &b = plain.nearest[c];
        found += b.triangle != HeartField::kNone ? 1 : 0;
        const bool same =
            a.triangle == b.triangle &&
            (b.triangle == HeartField::kNone || (a.signed_distance == b.signed_distance &&
                                                 a.point == b.point && a.normal == b.normal));
        mismatches += same ? 0 : 1;
      }
    }
  }
  EXPECT_EQ(mismatches, 0u);
  EXPECT_GT(found, 10000u);  // many queries did find the surface
  const HeartClearance& c = cached.clearance;
  EXPECT_EQ(c.searched + c.skipped, 400 * points.size());
  EXPECT_GT(c.skipped, c.searched);  // most queries were spared
  EXPECT_GT(c.travel, Real(0.005));  // the heart moved millimetres in 2 s
}

TEST(HeartClearance, AParticleMovedOntoTheHeartIsFoundAtOnce) {
  const HeartModel model = make_procedural_heart(HeartParams{});
  HeartField heart = make_heart_field(model, HeartPlayback{});
  TissueWorld world;
  const Vec3 on = heart.current[0], away = on + Real(0.05) * heart.normals[0];
  nearest_per_component_of_particle(heart, 0, 1, away, kHeartStepSearch);  // proved clear
  nearest_per_component_of_particle(heart, 0, 1, away, kHeartStepSearch);
  EXPECT_EQ(heart.clearance.skipped, 1u);
  nearest_per_component_of_particle(heart, 0, 1, on, kHeartStepSearch);
  bool found = false;
  for (const HeartField::Nearest& n : heart.nearest)
    found = found || (n.triangle != HeartField::kNone && n.distance2 < Real(1e-12));
  EXPECT_TRUE(found);
  EXPECT_EQ(heart.clearance.skipped, 1u);
}

}  // namespace
}  // namespace imasim::tissue
