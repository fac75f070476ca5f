#include "scene/heart_placement.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "geometry/closest_point.hpp"

namespace imasim::scene {
namespace {

Vec3 mean_of(const std::vector<Vec3>& points, std::size_t begin, std::size_t end) {
  Vec3 sum = Vec3::Zero();
  for (std::size_t i = begin; i < end; ++i)
    sum += points[i];
  return end > begin ? Vec3(sum / Real(end - begin)) : sum;
}

// Mean distance from the axis line through `centre` of the points whose position along the axis
// is in the outer `share` of the extent at the + end (or the - end).
Real end_radius(const std::vector<Vec3>& points, const Vec3& centre, const Vec3& axis, Real lo,
                Real hi, bool plus_end) {
  const Real share = Real(0.15) * (hi - lo);
  Real sum = 0;
  std::size_t n = 0;
  for (const Vec3& p : points) {
    const Real s = axis.dot(p - centre);
    if (plus_end ? s < hi - share : s > lo + share) continue;
    sum += (p - centre - s * axis).norm();
    ++n;
  }
  return n > 0 ? sum / Real(n) : Real(0);
}

// Automatic placement stops within this of the built-in heart's clearance (unit: m), or after
// this many moves.
constexpr Real kPlacementTolerance = Real(1e-4);
constexpr int kPlacementSteps = 8;

// The smallest distance over the cycle between the IMA's course and the heart's surface moved by
// `offset` (unit: m): every phase, every triangle, every centerline point.
Real ima_clearance(const tissue::HeartModel& heart, const std::vector<Vec3>& centerline,
                   const Vec3& offset) {
  Real best = std::numeric_limits<Real>::infinity();
  for (const std::vector<Vec3>& frame : heart.keyframes) {
    for (const geometry::Triangle& t : heart.topology.triangles) {
      for (const Vec3& p : centerline) {
        const geometry::TrianglePoint q =
            geometry::closest_point_on_triangle(p - offset, frame[t[0]], frame[t[1]], frame[t[2]]);
        best = std::min(best, q.distance2);
      }
    }
  }
  return std::sqrt(best);
}

std::string metres_text(Real m) {
  std::ostringstream s;
  s.precision(3);
  s << std::fixed << 1e3 * m << " mm";
  return s.str();
}

std::string vec_text(const Vec3& v) {
  std::ostringstream s;
  s.precision(4);
  s << std::fixed << "[" << v.x() << ", " << v.y() << ", " << v.z() << "]";
  return s.str();
}

}  // namespace

HeartShape measure_heart_shape(const tissue::HeartModel& heart) {
  const std::vector<Vec3>& x = heart.keyframes.front();
  HeartShape shape;
  shape.centre = mean_of(x, 0, x.size());
  Eigen::Matrix<Real, 3, 3> cov = Eigen::Matrix<Real, 3, 3>::Zero();
  for (const Vec3& p : x)
    cov += (p - shape.centre) * (p - shape.centre).transpose();
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<Real, 3, 3>> eigen(cov);
  Vec3 axis = eigen.eigenvectors().col(2).normalized();  // largest spread
  Vec3 across = eigen.eigenvectors().col(1).normalized();
  Real lo = 0, hi = 0;
  for (const Vec3& p : x) {
    lo = std::min(lo, axis.dot(p - shape.centre));
    hi = std::max(hi, axis.dot(p - shape.centre));
  }
  // The apex is the narrower end.
  if (end_radius(x, shape.centre, axis, lo, hi, true) >
      end_radius(x, shape.centre, axis, lo, hi, false)) {
    axis = -axis;
    std::swap(lo, hi);
    lo = -lo, hi = -hi;
  }
  // Across: towards the smaller of two components (the right ventricle), else as found.
  const std::size_t components = heart.component_start.size() - 1;
  if (components >= 2) {
    std::size_t smallest = 0;
    for (std::size_t c = 1; c < components; ++c) {
      if (heart.component_start[c + 1] - heart.component_start[c] <
          heart.component_start[smallest + 1] - heart.component_start[smallest])
        smallest = c;
    }
    const Vec3 towards =
        mean_of(x, heart.component_start[smallest], heart.component_start[smallest + 1]) -
        shape.centre;
    if (across.dot(towards) < 0) across = -across;
  }
  shape.long_axis = axis;
  shape.second_axis = across;
  shape.length = hi - lo;
  return shape;
}

std::string place_heart_automatically(tissue::HeartModel& heart, const ThoraxLayout& layout,
                                      const tissue::HeartModel& reference) {
  const HeartShape shape = measure_heart_shape(heart);
  const Vec3 target_axis = layout.heart_long_axis.normalized();
  const Vec3 target_across =
      (layout.heart_lateral - layout.heart_lateral.dot(target_axis) * target_axis).normalized();
  Eigen::Matrix<Real, 3, 3> from, to;
  from << shape.long_axis, shape.second_axis, shape.long_axis.cross(shape.second_axis);
  to << target_axis, target_across, target_axis.cross(target_across);
  const Eigen::Matrix<Real, 3, 3> rotation = to * from.transpose();
  for (std::vector<Vec3>& frame : heart.keyframes)
    for (Vec3& p : frame)
      p = layout.heart_centre + rotation * (p - shape.centre);
  // Along the line from the heart's centre to the IMA, until its closest approach to the IMA's
  // course over the cycle is the built-in heart's. The clearance changes by at most the move
  // (and by about the move where the nearest point lies along `up`): a few secant steps.
  const Vec3 up = (layout.ima_midpoint - layout.heart_centre).normalized();
  const Real target = ima_clearance(reference, layout.ima_centerline, Vec3::Zero());
  Real shift = 0;
  for (int k = 0; k < kPlacementSteps; ++k) {
    const Real gap = ima_clearance(heart, layout.ima_centerline, shift * up);
    if (std::abs(gap - target) < kPlacementTolerance) break;
    shift += gap - target;
  }
  for (std::vector<Vec3>& frame : heart.keyframes)
    for (Vec3& p : frame)
      p += shift * up;
  heart.topology.vertices = heart.keyframes.front();
  return "heart.placement = \"auto\": the phase meshes' long axis (" + metres_text(shape.length) +
         " long, apex at the narrower end) turned onto the scene's heart axis, centred at " +
         vec_text(layout.heart_centre + shift * up) + " m, as near the IMA as the built-in heart";
}

void check_heart_placement(tissue::HeartField& heart, const tissue::TissueWorld& world,
                           const ThoraxLayout& layout, Real tolerance, const std::string& remedy) {
  // The sheets (fascia, IMA, chest wall); strand particles reaching into the heart are put out
  // at set-up like any tissue generated at rest against it.
  const physics::Particles& P = world.state.particles;
  std::size_t inside = 0;
  Real deepest = 0;
  std::string deepest_in;
  for (const tissue::MeshObject& m : world.meshes) {
    for (std::uint32_t k = 0; k < m.particle_count; ++k) {
      const Real d =
          tissue::heart_signed_distance(heart, P.position[m.first_particle + k], Real(0.05));
      if (!(d < -tolerance)) continue;
      ++inside;
      if (-d > deepest) deepest = -d, deepest_in = m.name;
    }
  }
  if (inside > 0) {
    const Vec3 away = (layout.heart_centre - layout.ima_midpoint).normalized();
    throw HeartPlacementError(
        "the heart starts inside the tissue: " + std::to_string(inside) +
        " vertices of the fascia, the IMA and the chest wall lie inside it, up to " +
        metres_text(deepest) + " deep (" + deepest_in + "); " + remedy + " (moving it " +
        metres_text(deepest + Real(0.001)) + " along " + vec_text(away) +
        ", away from the IMA, would clear the deepest)");
  }
  const geometry::CylinderPatchSpec& wall = layout.wall;
  const Vec3 axis = wall.axis.normalized();
  Real beyond = 0;
  for (const Vec3& p : heart.current) {
    const Vec3 r = p - wall.origin;
    beyond = std::max(beyond, (r - r.dot(axis) * axis).norm() - wall.radius);
  }
  if (beyond > tolerance) {
    throw HeartPlacementError("the heart reaches " + metres_text(beyond) +
                              " beyond the chest wall's inner surface; " + remedy);
  }
}

}  // namespace imasim::scene
