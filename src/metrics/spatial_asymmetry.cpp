#include "metrics/spatial_asymmetry.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "geometry/closest_point.hpp"

namespace imasim::metrics {

namespace {

// The part of v perpendicular to the unit tangent t, normalised; zero if nothing is left.
Vec3 perpendicular(const Vec3& v, const Vec3& t) {
  const Vec3 p = v - v.dot(t) * t;
  const Real n = p.norm();
  return n > Real(1e-12) ? Vec3(p / n) : Vec3::Zero();
}

// The centerline's unit tangent at point k (the mean of its segments' directions there).
Vec3 tangent_at(std::span<const Vec3> c, std::size_t k) {
  const Vec3 before = k > 0 ? Vec3((c[k] - c[k - 1]).normalized()) : Vec3::Zero();
  const Vec3 after = k + 1 < c.size() ? Vec3((c[k + 1] - c[k]).normalized()) : Vec3::Zero();
  const Vec3 t = before + after;
  return t.norm() > 0 ? Vec3(t.normalized()) : after;
}

// Three significant digits, for messages.
std::string number_text(Real v) {
  std::ostringstream out;
  out.precision(3);
  out << v;
  return out.str();
}

Real triangle_area(const geometry::TriangleMesh& m, const geometry::Triangle& t) {
  const Vec3& a = m.vertices[t[0]];
  return Real(0.5) * (m.vertices[t[1]] - a).cross(m.vertices[t[2]] - a).norm();
}

// A triangle below a square micrometre has no direction to give: it is left out of the search.
constexpr Real kDegenerateArea = Real(1e-12);  // (unit: m^2)

// The heart's surface as a heart: finite, with triangles that have an area, of a heart's size
// (between a square millimetre and ten square metres: millimetres read as metres are a million
// times too large, metres read as millimetres a million times too small).
void check_heart(const geometry::TriangleMesh& heart) {
  Real area = 0;
  std::size_t with_area = 0;
  for (const geometry::Triangle& t : heart.triangles) {
    for (const std::uint32_t v : t) {
      if (v >= heart.vertices.size() || !heart.vertices[v].allFinite())
        throw SaiError("the heart surface has a missing or non-finite vertex");
    }
    const Real a = triangle_area(heart, t);
    area += a;
    with_area += a > kDegenerateArea ? 1 : 0;
  }
  if (with_area == 0)
    throw SaiError("the heart surface is degenerate: none of its " +
                   std::to_string(heart.triangles.size()) + " triangles has an area");
  if (!(area >= kMinHeartArea && area <= kMaxHeartArea)) {
    throw SaiError("the heart surface's area is " + number_text(area) +
                   " m^2, not a heart's (an adult's is a few hundred cm^2): check its units");
  }
}

Vec3 nearest_on_surface(const geometry::TriangleMesh& m, const Vec3& p) {
  Real best = std::numeric_limits<Real>::infinity();
  Vec3 at = Vec3::Zero();
  for (const geometry::Triangle& t : m.triangles) {
    if (!(triangle_area(m, t) > kDegenerateArea)) continue;
    const geometry::TrianglePoint q = geometry::closest_point_on_triangle(
        p, m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]);
    if (q.distance2 < best) best = q.distance2, at = q.point;
  }
  return at;
}

}  // namespace

SideReference make_side_reference(std::span<const Vec3> centerline,
                                  const geometry::TriangleMesh& heart) {
  if (centerline.size() < 2) throw SaiError("the centerline needs at least two points");
  if (heart.triangles.empty()) throw SaiError("the heart surface has no triangles");
  check_heart(heart);
  SideReference r;
  r.centerline.assign(centerline.begin(), centerline.end());
  for (std::size_t k = 0; k < centerline.size(); ++k) {
    if (!centerline[k].allFinite())
      throw SaiError("centerline point " + std::to_string(k + 1) + " is not finite");
    if ((centerline[k] - centerline[0]).norm() > kMaxSaiDistance)
      throw SaiError("centerline point " + std::to_string(k + 1) + " is more than " +
                     number_text(kMaxSaiDistance) +
                     " m from the first: not a vessel in a chest (millimetres read as metres?)");
    if (k > 0 && (centerline[k] - centerline[k - 1]).norm() < Real(1e-9))
      throw SaiError("centerline points " + std::to_string(k) + " and " + std::to_string(k + 1) +
                     " coincide");
  }
  for (std::size_t k = 0; k < centerline.size(); ++k) {
    const Vec3 toward = nearest_on_surface(heart, centerline[k]) - centerline[k];
    Vec3 side = perpendicular(toward, tangent_at(centerline, k));
    if (side == Vec3::Zero() && toward.norm() > Real(1e-9)) side = toward.normalized();
    if (side == Vec3::Zero())
      throw SaiError("the heart surface touches centerline point " + std::to_string(k + 1) +
                     ": no side can be told");
    r.heart_side.push_back(side);
  }
  return r;
}

SideDistance side_distance(const SideReference& r, const Vec3& tip) {
  const std::vector<Vec3>& c = r.centerline;
  Real best = std::numeric_limits<Real>::infinity();
  std::size_t segment = 0;
  Real along = 0;
  for (std::size_t k = 0; k + 1 < c.size(); ++k) {
    const Real t = geometry::closest_segment_parameter(tip, c[k], c[k + 1]);
    const Real d2 = (tip - (c[k] + t * (c[k + 1] - c[k]))).squaredNorm();
    if (d2 < best) best = d2, segment = k, along = t;
  }
  const Vec3 a = c[segment], b = c[segment + 1];
  const Vec3 foot = a + along * (b - a);
  const Vec3 offset = tip - foot;
  SideDistance s;
  s.distance = offset.norm();
  // The heart's side there: interpolated along the segment, perpendicular to it.
  const Vec3 heart =
      perpendicular((1 - along) * r.heart_side[segment] + along * r.heart_side[segment + 1],
                    (b - a).normalized());
  // Neutral (0) on the centerline and where the offset is square to the heart's side (to within
  // rounding: 1e-9 of the distance, so that a sample exactly beside the vessel is not given a
  // side by the last bits of the nearest-point search).
  const Real toward = offset.dot(heart);
  const Real tolerance = Real(1e-9) * s.distance;
  s.side = toward > tolerance ? -1 : toward < -tolerance ? 1 : 0;
  return s;
}

SaiResult spatial_asymmetry(const SideReference& r, std::span<const Vec3> tips, Real radius) {
  if (!(radius > 0) || !std::isfinite(radius)) throw SaiError("the radius R must be > 0");
  SaiResult out;
  out.samples = tips.size();
  if (tips.empty()) return out;
  Real sum = 0, distance = 0;
  std::size_t heart_side = 0;
  for (std::size_t i = 0; i < tips.size(); ++i) {
    if (!tips[i].allFinite())
      throw SaiError("trajectory sample " + std::to_string(i + 1) + " is not finite");
    const SideDistance s = side_distance(r, tips[i]);
    if (!(s.distance <= kMaxSaiDistance))
      throw SaiError("trajectory sample " + std::to_string(i + 1) + " is " +
                     number_text(s.distance) + " m from the centerline, more than " +
                     number_text(kMaxSaiDistance) +
                     " m: not a tool in a chest (millimetres read as metres?)");
    sum += Real(s.side) * s.distance / radius;  // eq. 20's term
    distance += s.distance;
    heart_side += s.side < 0 ? 1 : 0;
  }
  const Real n = Real(tips.size());
  out.sai = sum / n;
  out.mean_distance = distance / n;
  out.heart_side_fraction = Real(heart_side) / n;
  return out;
}

}  // namespace imasim::metrics
