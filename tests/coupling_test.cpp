// Offset coupling (eq. 8-9) on synthetic offsets.
#include <gtest/gtest.h>

#include "tissue/coupling.hpp"

namespace imasim::tissue {
namespace {

physics::Particles four_particles() {
  physics::Particles P;
  P.add(Vec3(0, 0, 0), 1, 0);  // 0: source
  P.add(Vec3(1, 0, 0), 1, 0);  // 1: destination
  P.add(Vec3(0, 1, 0), 1, 0);  // 2: source
  P.add(Vec3(1, 1, 0), 1, 0);  // 3: destination
  return P;
}

TEST(Coupling, Eq8CopiesASmallOffsetExactly) {
  physics::Particles P = four_particles();
  P.position[0] += Vec3(0.001, -0.002, 0.003);
  const OffsetCoupling c{"t", {{0, 1}}, 0.01, true, 0.8};
  apply_coupling(c, P);
  // Exact up to the rounding of rest + offset.
  EXPECT_LT(((P.position[1] - P.rest_position[1]) - (P.position[0] - P.rest_position[0])).norm(),
            1e-15);
}

TEST(Coupling, Eq8ClampsALargeOffsetToLambdaMax) {
  physics::Particles P = four_particles();
  const Vec3 offset(0.03, 0, -0.04);  // |O| = 0.05 m
  P.position[2] += offset;
  const OffsetCoupling c{"t", {{2, 3}}, 0.01, true, 0.8};
  apply_coupling(c, P);
  const Vec3 got = P.position[3] - P.rest_position[3];
  EXPECT_NEAR(got.norm(), 0.01, 1e-15);
  EXPECT_LT((got.normalized() - offset.normalized()).norm(), 1e-15);
  EXPECT_LT((got - Vec3(0.006, 0, -0.008)).norm(), 1e-15);
}

TEST(Coupling, Eq9WithBetaZeroDecaysByPointEight) {
  physics::Particles P = four_particles();
  P.position[1] += Vec3(0.01, 0.02, -0.005);
  P.position[0] += Vec3(0.5, 0.5, 0.5);  // ignored while beta = 0
  const OffsetCoupling c{"t", {{0, 1}}, 0.01, false, 0.8};
  for (int n = 1; n <= 5; ++n) {
    apply_coupling(c, P);
    const Vec3 expected = std::pow(0.8, n) * Vec3(0.01, 0.02, -0.005);
    EXPECT_LT((P.position[1] - P.rest_position[1] - expected).norm(), 1e-15);
  }
}

TEST(Coupling, Eq9WithBetaOneFollowsTheFat) {
  physics::Particles P = four_particles();
  P.position[2] += Vec3(0, 0, 0.004);  // fat point offset
  P.position[3] += Vec3(0.1, 0, 0);    // the vessel's own offset is replaced
  const OffsetCoupling c{"fat->ima", {{2, 3}}, 0.01, true, 0.8};
  apply_coupling(c, P);
  EXPECT_LT((P.position[3] - P.rest_position[3] - Vec3(0, 0, 0.004)).norm(), 1e-15);
}

TEST(Coupling, PairsEachDestinationWithItsNearestSource) {
  const physics::Particles P = four_particles();
  const auto pairs = nearest_source_pairs(P, {0, 2}, {1, 3}, 1.5);
  ASSERT_EQ(pairs.size(), 2u);
  EXPECT_EQ(pairs[0], std::make_pair(0u, 1u));
  EXPECT_EQ(pairs[1], std::make_pair(2u, 3u));
  EXPECT_TRUE(nearest_source_pairs(P, {0}, {3}, 1.0).empty());  // sqrt(2) away: out of reach
}

}  // namespace
}  // namespace imasim::tissue
