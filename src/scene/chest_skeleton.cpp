#include "scene/chest_skeleton.hpp"

#include <cmath>

#include "geometry/tube.hpp"

namespace imasim::scene {

namespace {

// A closed box from its 8 corners, c[i] with bit 0 = +u, bit 1 = +v, bit 2 = +w, where (u, v,
// w) is right-handed; triangles wound so that normals point outwards.
geometry::TriangleMesh box(const Vec3 (&c)[8]) {
  geometry::TriangleMesh m;
  m.vertices.assign(std::begin(c), std::end(c));
  m.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                 {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
  return m;
}

// An arc at distance `radius` from the wall's axis, at height z, between lateral positions
// x0 and x1 (measured as on the inner surface).
std::vector<Vec3> arc(const AnatomyParams& a, Real radius, Real x0, Real x1, Real z) {
  const Vec3 axis(a.sternum_position.x(), a.sternum_position.y() - a.chest_wall_radius, z);
  std::vector<Vec3> points;
  constexpr int kSamples = 12;
  for (int k = 0; k <= kSamples; ++k) {
    const Real x = x0 + (x1 - x0) * Real(k) / kSamples;
    points.push_back(axis + radius * wall_outward_normal(a, x));
  }
  return points;
}

}  // namespace

std::vector<DisplayMesh> make_chest_skeleton(const AnatomyParams& a, const ChestSkeletonParams& p) {
  std::vector<DisplayMesh> bones;
  const Real xs = a.sternum_position.x(), half = a.sternum_width / 2;
  const Real z0 = a.sternum_position.z() - a.rib_spacing,
             z1 = z0 + a.ima_course_length + 2 * a.rib_spacing;
  // The sternum: a flat slab over the midline, its back face `gap` outside the wall's surface
  // at its edges (the wall curves away from the midline, so its centre is further out).
  const Real back = wall_point(a, xs + half, 0).y() + p.gap;
  Vec3 corners[8];
  for (int i = 0; i < 8; ++i) {
    corners[i] = Vec3((i & 1) ? xs + half : xs - half, (i & 2) ? back + p.sternum_thickness : back,
                      (i & 4) ? z1 : z0);
  }
  // (x, y, z) with bit 0 = +x, bit 1 = +y, bit 2 = +z is right-handed.
  bones.push_back({"sternum", BoneKind::sternum, box(corners)});

  const Real centre_radius = a.chest_wall_radius + p.gap + p.rib_radius;
  const auto levels = static_cast<int>(std::floor(a.ima_course_length / a.rib_spacing)) + 1;
  for (int k = 0; k < levels; ++k) {
    const Real z = a.sternum_position.z() + a.rib_spacing * Real(k);
    const Real x_joint = xs + half + p.cartilage_length + p.cartilage_growth * Real(k);
    geometry::TubeSpec cartilage{arc(a, centre_radius, xs + half, x_joint, z), p.rib_radius, 8, 8};
    geometry::TubeSpec rib{arc(a, centre_radius, x_joint, xs + p.lateral_extent, z), p.rib_radius,
                           8, 24};
    const std::string n = std::to_string(k + 1);
    bones.push_back(
        {"costal_cartilage_" + n, BoneKind::costal_cartilage, geometry::make_tube(cartilage)});
    bones.push_back({"rib_" + n, BoneKind::rib, geometry::make_tube(rib)});
  }
  return bones;
}

}  // namespace imasim::scene
