#include "scene/anatomy.hpp"

#include <algorithm>
#include <cmath>

#include "tissue/random.hpp"

namespace imasim::scene {

namespace {

using A = AnatomyParams;

// Ranges in adults (SPEC S3; paper 2.1): the left IMA runs 2-3 cm from the sternal midline,
// a few millimetres under the wall's inner surface, behind costal cartilages 1-6.
const AnatomyRange kRanges[] = {
    {"sternum_width_m", &A::sternum_width, Real(0.025), Real(0.04)},
    {"ima_lateral_offset_m", &A::ima_lateral_offset, Real(0.02), Real(0.03)},
    {"ima_lateral_drift_m", &A::ima_lateral_drift, Real(0), Real(0.012)},
    {"ima_depth_m", &A::ima_depth, Real(0.003), Real(0.006)},
    {"ima_course_length_m", &A::ima_course_length, Real(0.15), Real(0.18)},
    {"chest_wall_radius_m", &A::chest_wall_radius, Real(0.09), Real(0.18)},
    {"fat_thickness_m", &A::fat_thickness, Real(0.007), Real(0.014)},
    {"fascia_width_m", &A::fascia_width, Real(0.03), Real(0.05)},
    {"fascia_length_m", &A::fascia_length, Real(0.12), Real(0.16)},
    {"rib_spacing_m", &A::rib_spacing, Real(0.02), Real(0.03)},
    {"heart_scale", &A::heart_scale, Real(0.85), Real(1.2)},
};

const AnatomyVectorSpread kSpreads[] = {
    {"sternum_position_m", &A::sternum_position, Vec3(Real(0.005), Real(0.003), Real(0.01))},
    {"heart_offset_m", &A::heart_offset, Vec3(Real(0.004), Real(0.003), Real(0.01))},
    {"heart_tilt_rad", &A::heart_tilt, Vec3(Real(0.12), Real(0.12), Real(0.12))},
};

// Inverse CDF of the triangular distribution on [lo, hi] with mode m, at u in [0, 1).
double triangular(double lo, double m, double hi, double u) {
  if (!(hi > lo)) return lo;
  const double split = (m - lo) / (hi - lo);
  return u < split ? lo + std::sqrt(u * (hi - lo) * (m - lo))
                   : hi - std::sqrt((1 - u) * (hi - lo) * (hi - m));
}

}  // namespace

std::span<const AnatomyRange> anatomy_ranges() {
  return kRanges;
}
std::span<const AnatomyVectorSpread> anatomy_vector_spreads() {
  return kSpreads;
}

AnatomyParams vary_anatomy(const AnatomyParams& typical) {
  if (typical.patient_seed == 0) return typical;
  AnatomyParams p = typical;
  tissue::SplitMix64 rng(typical.patient_seed);
  for (const AnatomyRange& r : kRanges) {
    const double mode = std::clamp(double(typical.*r.member), double(r.min), double(r.max));
    p.*r.member = Real(triangular(r.min, mode, r.max, double(rng.uniform())));
  }
  for (const AnatomyVectorSpread& s : kSpreads) {
    for (int k = 0; k < 3; ++k) {
      const double mode = double((typical.*s.member)[k]), d = double(s.spread[k]);
      (p.*s.member)[k] = Real(triangular(mode - d, mode, mode + d, double(rng.uniform())));
    }
  }
  return p;
}

Vec3 wall_outward_normal(const AnatomyParams& a, Real x) {
  const Real s = std::clamp((x - a.sternum_position.x()) / a.chest_wall_radius, Real(-1), Real(1));
  return Vec3(s, std::sqrt(1 - s * s), 0);
}

Vec3 wall_point(const AnatomyParams& a, Real x, Real z) {
  const Vec3 axis(a.sternum_position.x(), a.sternum_position.y() - a.chest_wall_radius, z);
  return axis + a.chest_wall_radius * wall_outward_normal(a, x);
}

ThoraxLayout layout_thorax(const AnatomyParams& a, const Vec3& heart_long_axis,
                           const Vec3& heart_lateral) {
  ThoraxLayout l;
  const Real R = a.chest_wall_radius, z0 = a.sternum_position.z(), L = a.ima_course_length;
  l.wall_axis_y = a.sternum_position.y() - R;

  // The IMA: `depth` under the wall along the normal, drifting laterally as it descends.
  constexpr int kCourseSamples = 9;
  for (int k = 0; k < kCourseSamples; ++k) {
    const Real f = Real(k) / Real(kCourseSamples - 1);
    const Real x = a.sternum_position.x() + a.ima_lateral_offset + f * a.ima_lateral_drift;
    const Real z = z0 + f * L;
    l.ima_centerline.push_back(wall_point(a, x, z) - a.ima_depth * wall_outward_normal(a, x));
  }
  const Real x_mid = a.sternum_position.x() + a.ima_lateral_offset + a.ima_lateral_drift / 2;
  l.ima_midpoint = wall_point(a, x_mid, z0 + L / 2) - a.ima_depth * wall_outward_normal(a, x_mid);

  // The wall patch covers the fascia and the IMA's drift with 15 mm to spare on each side, and
  // the course with 5 mm at each end. Angles turn from +y towards -x (tube.hpp's convention
  // with axis +z, reference +y), so a lateral position x sits at angle -asin(dx / R).
  const Real half_span = a.fascia_width / 2 + Real(0.015);
  const Real x_lo = x_mid - half_span - a.ima_lateral_drift / 2;
  const Real x_hi = x_mid + half_span + a.ima_lateral_drift / 2;
  auto angle_of = [&](Real x) {
    return -std::asin(std::clamp((x - a.sternum_position.x()) / R, Real(-1), Real(1)));
  };
  l.wall.origin = Vec3(a.sternum_position.x(), l.wall_axis_y, z0 - Real(0.005));
  l.wall.axis = Vec3::UnitZ();
  l.wall.reference = Vec3::UnitY();
  l.wall.radius = R;
  l.wall.angle0 = angle_of(x_hi);
  l.wall.angle1 = angle_of(x_lo);
  l.wall.length = L + Real(0.01);

  // The fascia: a flat rectangle tangent to the wall over the IMA's middle, fat_thickness
  // inside it, centred on the course. Turning the rectangle by -phi about z lays its x axis
  // along the wall's transverse tangent and its normal (+y) along the wall's outward normal.
  const Real phi = std::asin(std::clamp((x_mid - a.sternum_position.x()) / R, Real(-1), Real(1)));
  l.fascia_pose.rotation = axis_angle(Vec3::UnitZ(), -phi);
  const Vec3 centre = wall_point(a, x_mid, z0 + (L - a.fascia_length) / 2) -
                      a.fat_thickness * wall_outward_normal(a, x_mid);
  l.fascia_pose.translation = centre - l.fascia_pose.rotation * Vec3(a.fascia_width / 2, 0, 0);

  // The heart: its LV centre at an offset from the IMA's middle, tilted, scaled elsewhere.
  const Real tilt = a.heart_tilt.norm();
  const Mat3 turn = tilt > 0 ? axis_angle(a.heart_tilt / tilt, tilt) : Mat3::Identity();
  l.heart_centre = l.ima_midpoint + a.heart_offset;
  l.heart_long_axis = turn * heart_long_axis.normalized();
  l.heart_lateral = turn * heart_lateral;
  return l;
}

}  // namespace imasim::scene
