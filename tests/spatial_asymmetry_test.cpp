// The Spatial Asymmetry Index (metrics/spatial_asymmetry.hpp, eq. 20) on trajectories with
// known answers: a straight centerline with the heart on one side, both signs, the R scaling,
// samples along the heart-neutral direction, a curved centerline, and refused input.
#include "metrics/spatial_asymmetry.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace imasim::metrics {
namespace {

// A square of side 2 * half in the plane x = x0 (the heart's near surface, facing +x).
geometry::TriangleMesh plane_at_x(Real x0, Real half) {
  geometry::TriangleMesh m;
  m.vertices = {Vec3(x0, -half, -half), Vec3(x0, half, -half), Vec3(x0, half, half),
                Vec3(x0, -half, half)};
  m.triangles = {{0, 1, 2}, {0, 2, 3}};
  return m;
}

// The IMA along z over 10 cm, the heart 20 mm away on the -x side.
SideReference straight() {
  const std::vector<Vec3> c = {Vec3(0, 0, 0), Vec3(0, 0, 0.05), Vec3(0, 0, 0.1)};
  return make_side_reference(c, plane_at_x(-0.02, 0.5));
}

TEST(SpatialAsymmetry, HeartSideIsTowardTheHeartPerpendicularToTheVessel) {
  const SideReference r = straight();
  for (const Vec3& s : r.heart_side)
    EXPECT_LT((s - Vec3(-1, 0, 0)).norm(), 1e-12);
}

TEST(SpatialAsymmetry, BothSignsAndTheirMix) {
  const SideReference r = straight();
  const std::vector<Vec3> away(50, Vec3(0.004, 0, 0.03));     // 4 mm from the heart's side
  const std::vector<Vec3> toward(50, Vec3(-0.002, 0, 0.07));  // 2 mm toward it
  const SaiResult a = spatial_asymmetry(r, away);
  EXPECT_NEAR(a.sai, 2.0, 1e-12);  // 4 mm / 2 mm, positive
  EXPECT_EQ(a.samples, 50u);
  EXPECT_NEAR(a.mean_distance, 0.004, 1e-15);
  EXPECT_EQ(a.heart_side_fraction, 0);
  const SaiResult b = spatial_asymmetry(r, toward);
  EXPECT_NEAR(b.sai, -1.0, 1e-12);
  EXPECT_EQ(b.heart_side_fraction, 1);
  std::vector<Vec3> both = away;
  both.insert(both.end(), toward.begin(), toward.end());
  const SaiResult m = spatial_asymmetry(r, both);
  EXPECT_NEAR(m.sai, 0.5, 1e-12);
  EXPECT_NEAR(m.heart_side_fraction, 0.5, 1e-15);
  EXPECT_NEAR(m.mean_distance, 0.003, 1e-15);
}

TEST(SpatialAsymmetry, TheRadiusScalesTheIndex) {
  const SideReference r = straight();
  const std::vector<Vec3> tips = {Vec3(0.003, 0.001, 0.02), Vec3(-0.001, 0.0, 0.04)};
  const Real at2 = spatial_asymmetry(r, tips).sai;
  // d = (sqrt(10) mm away, 1 mm toward): (sqrt(10) - 1) / 2 / 2.
  EXPECT_NEAR(at2, (std::sqrt(10.0) - 1) / 4, 1e-12);
  EXPECT_NEAR(spatial_asymmetry(r, tips, 0.001).sai, 2 * at2, 1e-12);
  EXPECT_NEAR(spatial_asymmetry(r, tips, 0.004).sai, at2 / 2, 1e-12);
}

TEST(SpatialAsymmetry, NeutralSamplesCountInNAndDistanceOnly) {
  const SideReference r = straight();
  // Straight out along y: as far from the heart's side as on it; on the centerline: no side.
  const std::vector<Vec3> tips = {Vec3(0, 0.004, 0.05), Vec3(0, 0, 0.06), Vec3(0.002, 0, 0.05)};
  const SaiResult s = spatial_asymmetry(r, tips);
  EXPECT_NEAR(s.sai, 1.0 / 3, 1e-12);  // only the last counts: +1
  EXPECT_NEAR(s.mean_distance, 0.002, 1e-15);
  EXPECT_EQ(s.samples, 3u);
}

TEST(SpatialAsymmetry, ACurvedVesselAroundTheHeart) {
  // A quarter circle of radius 50 mm about the y axis, the heart a small tetrahedron at the
  // centre: the heart's side is inward everywhere.
  std::vector<Vec3> c;
  for (int k = 0; k <= 90; ++k) {
    const Real a = Real(k) * std::numbers::pi / 180;
    c.emplace_back(0.05 * std::cos(a), 0, 0.05 * std::sin(a));
  }
  geometry::TriangleMesh heart;
  heart.vertices = {Vec3(0.001, 0, 0), Vec3(-0.001, 0.001, 0), Vec3(-0.001, -0.001, 0.001),
                    Vec3(-0.001, -0.001, -0.001)};
  heart.triangles = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
  const SideReference r = make_side_reference(c, heart);
  std::vector<Vec3> outside, inside;
  for (int k = 5; k < 85; k += 10) {
    const Real a = (Real(k) + Real(0.5)) * std::numbers::pi / 180;  // between polyline points
    const Vec3 radial(std::cos(a), 0, std::sin(a));
    outside.push_back(0.053 * radial);
    inside.push_back(0.048 * radial);
  }
  // The polyline's chords sit inside the arc by at most r (1 - cos(0.5 deg)) = 1.9 um.
  EXPECT_NEAR(spatial_asymmetry(r, outside).sai, 1.5, 2e-3);
  EXPECT_NEAR(spatial_asymmetry(r, inside).sai, -1.0, 2e-3);
}

TEST(SpatialAsymmetry, PastTheEndsTheNearestEndCounts) {
  const SideReference r = straight();
  const SideDistance s = side_distance(r, Vec3(0.003, 0, 0.104));
  EXPECT_NEAR(s.distance, 0.005, 1e-15);
  EXPECT_EQ(s.side, 1);
}

TEST(SpatialAsymmetry, BadInputIsRefused) {
  const geometry::TriangleMesh heart = plane_at_x(-0.02, 0.5);
  const std::vector<Vec3> one = {Vec3(0, 0, 0)};
  const std::vector<Vec3> repeated = {Vec3(0, 0, 0), Vec3(0, 0, 0), Vec3(0, 0, 0.1)};
  const std::vector<Vec3> through = {Vec3(-0.02, 0, 0), Vec3(-0.02, 0, 0.1)};
  EXPECT_THROW(make_side_reference(one, heart), SaiError);
  EXPECT_THROW(make_side_reference(repeated, heart), SaiError);
  EXPECT_THROW(make_side_reference(through, heart), SaiError);
  EXPECT_THROW(make_side_reference(through, geometry::TriangleMesh{}), SaiError);
  const SideReference r = straight();
  const std::vector<Vec3> tips = {Vec3(0, 0, 0.01), Vec3(NAN, 0, 0)};
  EXPECT_THROW(spatial_asymmetry(r, tips), SaiError);
  EXPECT_THROW(spatial_asymmetry(r, {}, 0), SaiError);
  EXPECT_EQ(spatial_asymmetry(r, {}).samples, 0u);
  // Beyond a chest: a sample 20 m away, a centerline 20 m long (millimetres read as metres).
  EXPECT_THROW(spatial_asymmetry(r, std::vector<Vec3>{Vec3(20, 0, 0)}), SaiError);
  EXPECT_NO_THROW(spatial_asymmetry(r, std::vector<Vec3>{Vec3(5, 0, 0)}));
  const std::vector<Vec3> long_line = {Vec3(0, 0, 0), Vec3(0, 0, 20)};
  EXPECT_THROW(make_side_reference(long_line, plane_at_x(-0.02, 20)), SaiError);
}

// A heart that is not one: every triangle without area, or of an area no heart has in metres.
// A degenerate triangle beside good ones is left out of the nearest-point search.
TEST(SpatialAsymmetry, DegenerateOrMisScaledHeartsAreRefused) {
  const std::vector<Vec3> c = {Vec3(0, 0, 0), Vec3(0, 0, 0.1)};
  geometry::TriangleMesh collinear;
  collinear.vertices = {Vec3(-0.02, 0, 0), Vec3(-0.03, 0, 0), Vec3(-0.04, 0, 0)};
  collinear.triangles = {{0, 1, 2}};
  EXPECT_THROW(make_side_reference(c, collinear), SaiError);
  EXPECT_THROW(make_side_reference(c, plane_at_x(-0.02, 0.0004)), SaiError);  // 0.64 mm^2
  EXPECT_THROW(make_side_reference(c, plane_at_x(-20, 500)), SaiError);       // 10^6 m^2
  // A sliver nearer the vessel, on the other side, with no area: the plane still gives the side.
  geometry::TriangleMesh with_sliver = plane_at_x(-0.02, 0.5);
  const auto base = std::uint32_t(with_sliver.vertices.size());
  with_sliver.vertices.insert(with_sliver.vertices.end(),
                              {Vec3(0.001, 0, 0), Vec3(0.001, 0, 0.05), Vec3(0.001, 0, 0.1)});
  with_sliver.triangles.push_back({base, base + 1, base + 2});
  const SideReference r = make_side_reference(c, with_sliver);
  EXPECT_EQ(side_distance(r, Vec3(-0.001, 0, 0.05)).side, -1);  // toward the plane: the heart
}

}  // namespace
}  // namespace imasim::metrics
