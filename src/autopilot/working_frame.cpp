#include "autopilot/working_frame.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/closest_point.hpp"
#include "scene/anatomy.hpp"
#include "tissue/heart.hpp"

namespace imasim::autopilot {

namespace {

// The heart's motion is sampled at this many phases of a beat.
constexpr int kBeatSamples = 40;
// Heart vertices this close to the segment count for its excursion (unit: m).
constexpr Real kExcursionReach = Real(0.03);

std::vector<Real> arc_lengths(const std::vector<Vec3>& line) {
  std::vector<Real> arc(line.size(), 0);
  for (std::size_t i = 1; i < line.size(); ++i)
    arc[i] = arc[i - 1] + (line[i] - line[i - 1]).norm();
  return arc;
}

// The point at arc length s of a polyline with arc lengths `arc`.
Vec3 along(const std::vector<Vec3>& line, const std::vector<Real>& arc, Real s) {
  s = std::clamp(s, Real(0), arc.back());
  const auto it = std::upper_bound(arc.begin(), arc.end(), s);
  const std::size_t i = it == arc.end() ? arc.size() - 1 : std::size_t(it - arc.begin());
  if (i == 0) return line.front();
  const Real span = arc[i] - arc[i - 1];
  const Real u = span > 0 ? (s - arc[i - 1]) / span : Real(1);
  return (1 - u) * line[i - 1] + u * line[i];
}

Real heart_excursion(const session::SurgicalSession& s, const std::vector<Vec3>& segment) {
  const tissue::HeartField& heart = s.scene.heart;
  if (!heart.playback.beating) return 0;
  std::vector<std::uint32_t> near;
  for (std::uint32_t v = 0; v < heart.reference.size(); ++v)
    if (distance_to_segment(heart.reference[v], segment) < kExcursionReach) near.push_back(v);
  std::vector<Vec3> shape(heart.reference.size());
  Real largest = 0;
  for (int k = 0; k < kBeatSamples; ++k) {
    tissue::interpolate_heart(heart.model, Real(k) / kBeatSamples, shape);
    for (std::uint32_t v : near)
      largest = std::max(largest, (shape[v] - heart.reference[v]).norm());
  }
  return largest;
}

const scene::Port* port_named(const session::SurgicalSession& s, const std::string& name) {
  for (const scene::Port& p : s.scene.ports)
    if (p.name == name) return &p;
  return nullptr;
}

}  // namespace

Vec3 WorkingFrame::point_at(Real s) const {
  return along(segment, arc, s);
}

Vec3 WorkingFrame::tangent_at(Real s) const {
  constexpr Real kHalfSpan = Real(0.002);
  const Real a = std::max(s - kHalfSpan, Real(0)), b = std::min(s + kHalfSpan, length());
  return (point_at(b) - point_at(a)).normalized();
}

Real WorkingFrame::heart_distance(const Vec3& p) const {
  Real best = std::numeric_limits<Real>::infinity();
  for (const auto& t : heart_triangles) {
    best = std::min(
        best,
        geometry::closest_point_on_triangle(p, heart[t[0]], heart[t[1]], heart[t[2]]).distance2);
  }
  return std::sqrt(best);
}

WorkingFrame make_working_frame(const session::SurgicalSession& s, Real segment_length) {
  const std::vector<Vec3>& course = s.scene.layout.ima_centerline;
  if (course.size() < 2) throw std::invalid_argument("the scene has no IMA course");
  const std::vector<Real> course_arc = arc_lengths(course);
  const Real total = course_arc.back();
  if (!(segment_length > 0) || segment_length > total) {
    throw std::invalid_argument("the IMA's course (" + std::to_string(total) +
                                " m) is shorter than the segment to harvest (" +
                                std::to_string(segment_length) + " m)");
  }
  WorkingFrame f;
  // The segment: centred on the course, where the fascia covers it; a point every mm.
  const Real start = (total - segment_length) / 2;
  const int points = int(std::ceil(segment_length / Real(0.001))) + 1;
  for (int i = 0; i < points; ++i)
    f.segment.push_back(
        along(course, course_arc, start + segment_length * Real(i) / Real(points - 1)));
  f.arc = arc_lengths(f.segment);

  const Vec3 middle = f.point_at(f.length() / 2);
  const Vec3 tangent = f.tangent_at(f.length() / 2);
  f.wall_normal = scene::wall_outward_normal(s.scene.patient, middle.x());
  f.wall_normal = (f.wall_normal - f.wall_normal.dot(tangent) * tangent).normalized();
  const Vec3 across = f.wall_normal.cross(tangent).normalized();
  const Vec3 to_heart = s.scene.layout.heart_centre - middle;
  f.away = to_heart.dot(across) > 0 ? Vec3(-across) : across;

  const Pose& fascia = s.scene.layout.fascia_pose;
  const Vec3 fascia_normal = fascia.rotation.col(1);
  f.fascia_depth =
      std::abs((middle - fascia.translation).dot(fascia_normal) / f.wall_normal.dot(fascia_normal));
  f.wall_height =
      (scene::wall_point(s.scene.patient, middle.x(), middle.z()) - middle).dot(f.wall_normal);

  f.heart = s.scene.heart.reference;
  for (const auto& t : s.scene.heart.model.topology.triangles)
    f.heart_triangles.push_back({t[0], t[1], t[2]});
  f.heart_excursion = heart_excursion(s, f.segment);

  const scene::Port* left = port_named(s, "left_instrument");
  const scene::Port* right = port_named(s, "right_instrument");
  if (!left || !right) throw std::invalid_argument("the scene has no instrument ports");
  f.forceps_port = left->position;
  f.hook_port = right->position;
  f.forceps_start = s.stations[0].pose;
  f.hook_start = s.stations[1].pose;
  f.hook_arm = s.stations[1].arm;
  return f;
}

Real distance_to_segment(const Vec3& p, const std::vector<Vec3>& line) {
  Real best = std::numeric_limits<Real>::infinity();
  for (std::size_t i = 1; i < line.size(); ++i) {
    const Real u = geometry::closest_segment_parameter(p, line[i - 1], line[i]);
    best = std::min(best, (p - ((1 - u) * line[i - 1] + u * line[i])).norm());
  }
  return best;
}

}  // namespace imasim::autopilot
