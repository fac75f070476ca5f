// Offset coupling (eq. 8-9) on synthetic offsets.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

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
  const OffsetCoupling c{"t", {{0, 1}}, 0.01, Beta::one, 0.8};
  apply_coupling(c, P);
  // Exact up to the rounding of rest + offset.
  EXPECT_LT(((P.position[1] - P.rest_position[1]) - (P.position[0] - P.rest_position[0])).norm(),
            1e-15);
}

TEST(Coupling, Eq8ClampsALargeOffsetToLambdaMax) {
  physics::Particles P = four_particles();
  const Vec3 offset(0.03, 0, -0.04);  // |O| = 0.05 m
  P.position[2] += offset;
  const OffsetCoupling c{"t", {{2, 3}}, 0.01, Beta::one, 0.8};
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
  const OffsetCoupling c{"t", {{0, 1}}, 0.01, Beta::zero, 0.8};
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
  const OffsetCoupling c{"fat->ima", {{2, 3}}, 0.01, Beta::one, 0.8};
  apply_coupling(c, P);
  EXPECT_LT((P.position[3] - P.rest_position[3] - Vec3(0, 0, 0.004)).norm(), 1e-15);
}

// eq. 9's beta as the coupling state indicator: a pair follows its source while the source is
// manipulated (its strand held) and relaxes by 0.8 otherwise, each pair on its own.
TEST(Coupling, BetaByManipulationFollowsHeldFatAndRelaxesOtherwise) {
  physics::Particles P = four_particles();
  P.position[0] += Vec3(0, 0.004, 0);  // held fat, moved
  P.position[2] += Vec3(0, 0.004, 0);  // fat moved, not held
  P.position[1] += Vec3(0.002, 0, 0);
  P.position[3] += Vec3(0.002, 0, 0);
  const OffsetCoupling c{"fat->ima", {{0, 1}, {2, 3}}, 0.01, Beta::manipulated, 0.8};
  const std::vector<std::uint8_t> manipulated = {1, 0, 0, 0};
  const CouplingFlags flags{{}, manipulated};
  EXPECT_TRUE(pair_follows(c, 0, flags));
  EXPECT_FALSE(pair_follows(c, 2, flags));
  // Inside the solve: a follow row for the held fat's pair only.
  std::vector<physics::FollowRow> rows;
  append_follow_rows(c, P, P.rest_position, flags, rows);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].destination, 1u);
  // After the step: the other relaxes, the follower is left to its row.
  apply_coupling(c, P, P.rest_position, {}, 0, flags, PairsApplied::relaxing);
  EXPECT_LT((P.position[3] - P.rest_position[3] - Vec3(0.0016, 0, 0)).norm(), 1e-15);
  EXPECT_LT((P.position[1] - P.rest_position[1] - Vec3(0.002, 0, 0)).norm(), 1e-15);
  apply_coupling(c, P, P.rest_position, {}, 0, flags, PairsApplied::following);
  EXPECT_LT((P.position[1] - P.rest_position[1] - Vec3(0, 0.004, 0)).norm(), 1e-15);
  // No decay (1): the destination is left to its own physics when the fat is not held.
  const OffsetCoupling free{"fat->fascia", {{2, 3}}, 0.01, Beta::manipulated, 1};
  const Vec3 before = P.position[3];
  apply_coupling(free, P, P.rest_position, {}, 0, flags, PairsApplied::relaxing);
  EXPECT_EQ(P.position[3], before);
}

// Manipulated fat is the tool's: a coupling that yields leaves it alone, and a held or fixed
// destination is left by every coupling.
TEST(Coupling, YieldingCouplingsLeaveManipulatedFatAlone) {
  physics::Particles P = four_particles();
  P.position[0] += Vec3(0.003, 0, 0);  // the vessel moved
  P.position[2] += Vec3(0.003, 0, 0);
  const OffsetCoupling c{"ima->fat", {{0, 1}, {2, 3}}, 0.01, Beta::one, 0.8, true};
  const std::vector<std::uint8_t> manipulated = {0, 1, 0, 0};
  std::vector<physics::FollowRow> rows;
  append_follow_rows(c, P, P.rest_position, {{}, manipulated}, rows);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].destination, 3u);
  const std::vector<std::uint8_t> held = {0, 0, 0, 1};
  rows.clear();
  append_follow_rows(c, P, P.rest_position, {held, {}}, rows);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].destination, 1u);
  P.fix(1);
  rows.clear();
  append_follow_rows(c, P, P.rest_position, {}, rows);
  ASSERT_EQ(rows.size(), 1u);
  EXPECT_EQ(rows[0].destination, 3u);
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
