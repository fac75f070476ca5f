// The procedural thorax: the layout follows the anatomical parameters, variation stays in the
// documented ranges with the documented distribution, and varied patients simulate soundly.
#include "scene/anatomy.hpp"

#include <gtest/gtest.h>

#include "geometry/mesh_checks.hpp"
#include "physics/executor.hpp"
#include "scene/chest_skeleton.hpp"
#include "scene/thorax_scene.hpp"

namespace imasim::scene {
namespace {

ThoraxLayout typical_layout(const AnatomyParams& a) {
  const tissue::HeartParams heart;
  return layout_thorax(a, heart.long_axis, heart.lateral);
}

// Distance of p from the chest wall's cylinder axis.
Real from_axis(const AnatomyParams& a, const Vec3& p) {
  const Vec3 axis(a.sternum_position.x(), a.sternum_position.y() - a.chest_wall_radius, p.z());
  return (p - axis).norm();
}

TEST(Anatomy, ImaRunsAtItsOffsetAndDepthUnderTheWall) {
  AnatomyParams a;
  a.sternum_position = Vec3(-0.02, 0.003, 0.01);
  a.ima_lateral_drift = 0.008;
  const ThoraxLayout l = typical_layout(a);
  const Vec3& cranial = l.ima_centerline.front();
  const Vec3& caudal = l.ima_centerline.back();
  // Lateral offset measured along the wall's surface direction: x of the point on the wall.
  auto lateral_of = [&](const Vec3& p) {
    const Vec3 axis(a.sternum_position.x(), a.sternum_position.y() - a.chest_wall_radius, p.z());
    const Vec3 radial = (p - axis).normalized();
    return a.chest_wall_radius * radial.x();  // x of the wall point above p, from the midline
  };
  EXPECT_NEAR(lateral_of(cranial), a.ima_lateral_offset, 1e-15);
  EXPECT_NEAR(lateral_of(caudal), a.ima_lateral_offset + a.ima_lateral_drift, 1e-15);
  for (const Vec3& p : l.ima_centerline)
    EXPECT_NEAR(from_axis(a, p), a.chest_wall_radius - a.ima_depth, 1e-15);
  EXPECT_NEAR(cranial.z(), a.sternum_position.z(), 1e-15);
  EXPECT_NEAR(caudal.z() - cranial.z(), a.ima_course_length, 1e-15);
  Real length = 0;
  for (std::size_t k = 1; k < l.ima_centerline.size(); ++k)
    length += (l.ima_centerline[k] - l.ima_centerline[k - 1]).norm();
  EXPECT_GE(length, 0.15);  // a 10 cm segment with room at both ends
}

TEST(Anatomy, FasciaLiesFatThicknessInsideTheWallOverTheIma) {
  AnatomyParams a;
  a.fat_thickness = 0.012;
  a.chest_wall_radius = 0.1;
  const ThoraxLayout l = typical_layout(a);
  // The rectangle's centre line touches the cylinder R - fat inside; its edges, w/2 away along
  // the tangent, lie sqrt((R - fat)^2 + (w/2)^2) from the axis.
  const Real inner = a.chest_wall_radius - a.fat_thickness;
  for (Real z : {0.0, a.fascia_length}) {
    const Vec3 centre = l.fascia_pose.apply(Vec3(a.fascia_width / 2, 0, z));
    const Vec3 edge = l.fascia_pose.apply(Vec3(0, 0, z));
    EXPECT_NEAR(from_axis(a, centre), inner, 1e-15);
    EXPECT_NEAR(from_axis(a, edge), std::hypot(inner, a.fascia_width / 2), 1e-15);
  }
  // The fascia's normal (+y locally) points into the wall at its centre.
  const Vec3 normal = l.fascia_pose.rotate(Vec3::UnitY());
  const Vec3 centre = l.fascia_pose.apply(Vec3(a.fascia_width / 2, 0, 0));
  const Vec3 axis(a.sternum_position.x(), a.sternum_position.y() - a.chest_wall_radius, 0);
  EXPECT_NEAR(normal.dot((centre - axis).normalized()), 1, 1e-15);
  // And it is centred, across, over the IMA's middle: the same direction from the axis.
  const Vec3 mid_axis(axis.x(), axis.y(), l.ima_midpoint.z());
  EXPECT_NEAR(normal.dot((l.ima_midpoint - mid_axis).normalized()), 1, 1e-15);
}

TEST(Anatomy, SeedZeroIsTheTypicalPatientAndSeedsAreReproducible) {
  AnatomyParams typical;
  const AnatomyParams same = vary_anatomy(typical);
  EXPECT_EQ(same.ima_depth, typical.ima_depth);
  EXPECT_EQ(same.heart_offset, typical.heart_offset);
  typical.patient_seed = 42;
  const AnatomyParams a = vary_anatomy(typical), b = vary_anatomy(typical);
  for (const AnatomyRange& r : anatomy_ranges())
    EXPECT_EQ(a.*r.member, b.*r.member) << r.name;
  typical.patient_seed = 43;
  const AnatomyParams c = vary_anatomy(typical);
  int differ = 0;
  for (const AnatomyRange& r : anatomy_ranges())
    differ += a.*r.member != c.*r.member;
  EXPECT_EQ(differ, static_cast<int>(anatomy_ranges().size()));
}

TEST(Anatomy, VariationStaysInRangeWithATriangularDistribution) {
  AnatomyParams typical;
  constexpr int kPatients = 4000;
  std::vector<double> sum(anatomy_ranges().size(), 0.0);
  for (int n = 1; n <= kPatients; ++n) {
    typical.patient_seed = static_cast<std::uint64_t>(n);
    const AnatomyParams p = vary_anatomy(typical);
    std::size_t k = 0;
    for (const AnatomyRange& r : anatomy_ranges()) {
      const Real v = p.*r.member;
      ASSERT_GE(v, r.min) << r.name;
      ASSERT_LE(v, r.max) << r.name;
      sum[k++] += v;
    }
    for (const AnatomyVectorSpread& s : anatomy_vector_spreads()) {
      const Vec3 d = p.*s.member - typical.*s.member;
      for (int i = 0; i < 3; ++i)
        ASSERT_LE(std::abs(d[i]), s.spread[i]) << s.name;
    }
  }
  // The triangular distribution on [a, b] with mode c has mean (a + b + c) / 3 and variance
  // (a^2 + b^2 + c^2 - ab - ac - bc) / 18: the sample mean lies within 4 standard errors.
  std::size_t k = 0;
  for (const AnatomyRange& r : anatomy_ranges()) {
    const double a = r.min, b = r.max, c = std::clamp(double(typical.*r.member), a, b);
    const double mean = (a + b + c) / 3;
    const double sd = std::sqrt((a * a + b * b + c * c - a * b - a * c - b * c) / 18);
    EXPECT_NEAR(sum[k++] / kPatients, mean, 4 * sd / std::sqrt(double(kPatients))) << r.name;
  }
}

TEST(ChestSkeleton, BonesLieInTheWallAndTheImaBehindTheCartilages) {
  AnatomyParams a;
  const std::vector<DisplayMesh> bones = make_chest_skeleton(a);
  const ThoraxLayout l = typical_layout(a);
  const auto levels = static_cast<std::size_t>(std::floor(a.ima_course_length / a.rib_spacing)) + 1;
  ASSERT_EQ(bones.size(), 1 + 2 * levels);
  EXPECT_EQ(bones[0].kind, BoneKind::sternum);
  geometry::MeshCheckOptions closed;
  closed.require_closed = true;
  EXPECT_EQ(geometry::first_mesh_defect(bones[0].mesh, closed), "");
  EXPECT_GT(geometry::enclosed_volume(bones[0].mesh.vertices, bones[0].mesh.triangles), 0);
  for (const DisplayMesh& bone : bones) {
    EXPECT_EQ(geometry::first_mesh_defect(bone.mesh), "") << bone.name;
    for (const Vec3& v : bone.mesh.vertices)  // outside the cavity: in or beyond the wall
      ASSERT_GE(from_axis(a, v), a.chest_wall_radius) << bone.name;
  }
  // The IMA (x from the midline, measured at the wall) passes behind every costal cartilage.
  for (std::size_t k = 1; k < bones.size(); k += 2) {
    ASSERT_EQ(bones[k].kind, BoneKind::costal_cartilage);
    Real lo = 1, hi = -1;
    for (const Vec3& v : bones[k].mesh.vertices)
      lo = std::min(lo, v.x()), hi = std::max(hi, v.x());
    const Real z = bones[k].mesh.vertices[0].z();
    Real ima_x = 0;  // the centerline's x at the cartilage's level
    for (std::size_t i = 1; i < l.ima_centerline.size(); ++i) {
      const Vec3 &p = l.ima_centerline[i - 1], &q = l.ima_centerline[i];
      if (z >= p.z() - 1e-12 && z <= q.z() + 1e-12)
        ima_x = p.x() + (q.x() - p.x()) * (z - p.z()) / (q.z() - p.z());
    }
    EXPECT_LT(lo, ima_x) << bones[k].name;
    EXPECT_GT(hi, ima_x) << bones[k].name;
  }
}

TEST(Anatomy, VariedPatientsSimulateWithNoTissueInTheHeart) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    ThoraxSceneParams p = default_thorax_scene_params();
    p.anatomy.patient_seed = seed;
    ThoraxScene s = make_thorax_scene(p);
    EXPECT_NE(s.patient.ima_depth, p.anatomy.ima_depth);
    physics::Executor exec(1);
    for (int n = 0; n < 200; ++n)
      ASSERT_TRUE(step_thorax_scene(s, exec).ok()) << "seed " << seed << " step " << n;
    const physics::Particles& P = s.patch.world.state.particles;
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (P.inverse_mass[i] == 0) continue;
      ASSERT_TRUE(P.position[i].allFinite());
      EXPECT_GE(tissue::heart_signed_distance(s.heart, P.position[i], 0.03), 0.0)
          << "seed " << seed << " particle " << i;
    }
    EXPECT_GT(s.patch.world.strands[s.patch.ima_fat].strand_count, 100u) << "seed " << seed;
    EXPECT_GT(s.patch.world.strands[s.patch.fascia_fat].strand_count, 100u) << "seed " << seed;
  }
}

}  // namespace
}  // namespace imasim::scene
