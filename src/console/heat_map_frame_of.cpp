#include "console/heat_map_frame_of.hpp"

#include <algorithm>
#include <map>
#include <set>
#include <stdexcept>

namespace imasim::console {

namespace {

double cross(const metrics::PlanePoint& o, const metrics::PlanePoint& a,
             const metrics::PlanePoint& b) {
  return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
}

// Plane points back to 3-D points on the plane (they project to themselves).
std::vector<Vec3> on_plane(const metrics::HeatMapFrame& f,
                           std::span<const metrics::PlanePoint> points) {
  std::vector<Vec3> out;
  out.reserve(points.size());
  for (const metrics::PlanePoint& p : points)
    out.push_back(f.origin + Real(p.x()) * f.u + Real(p.y()) * f.v);
  return out;
}

metrics::HeatMapOutline hull_outline(const metrics::HeatMapFrame& f, const char* name,
                                     const std::array<double, 3>& rgb,
                                     std::span<const Vec3> points) {
  metrics::HeatMapOutline o;
  o.name = name;
  o.rgb = rgb;
  o.closed = true;
  o.points = on_plane(f, convex_hull(metrics::project(f, points)));
  return o;
}

}  // namespace

std::vector<metrics::PlanePoint> convex_hull(std::vector<metrics::PlanePoint> p) {
  std::sort(p.begin(), p.end(), [](const metrics::PlanePoint& a, const metrics::PlanePoint& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<metrics::PlanePoint> hull(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {  // lower hull
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], p[i]) <= 0)
      --k;
    hull[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, lower = k + 1; i-- > 0;) {  // upper hull
    while (k >= lower && cross(hull[k - 2], hull[k - 1], p[i]) <= 0)
      --k;
    hull[k++] = p[i];
  }
  hull.resize(k - 1);  // the last point repeats the first
  return hull;
}

std::vector<std::uint32_t> longest_boundary_loop(std::span<const geometry::Triangle> triangles) {
  std::set<std::pair<std::uint32_t, std::uint32_t>> directed;
  for (const geometry::Triangle& t : triangles)
    for (int e = 0; e < 3; ++e)
      directed.insert({t[std::size_t(e)], t[std::size_t((e + 1) % 3)]});
  // A boundary edge runs a -> b with no b -> a; following them walks each hole or rim.
  std::map<std::uint32_t, std::uint32_t> next;
  for (const auto& [a, b] : directed)
    if (!directed.contains({b, a})) next.emplace(a, b);
  std::vector<std::uint32_t> longest;
  std::set<std::uint32_t> seen;
  for (const auto& [start, unused] : next) {
    if (seen.contains(start)) continue;
    std::vector<std::uint32_t> loop;
    for (std::uint32_t v = start; !seen.contains(v);) {
      seen.insert(v);
      loop.push_back(v);
      const auto it = next.find(v);
      if (it == next.end()) break;  // an open chain (a non-manifold rim): kept as far as it goes
      v = it->second;
    }
    if (loop.size() > longest.size()) longest = std::move(loop);
  }
  return longest;
}

metrics::HeatMapFrame heat_map_frame_of(const session::SurgicalSession& s) {
  const scene::ThoraxLayout& layout = s.scene.layout;
  const std::vector<Vec3>& line = layout.ima_centerline;
  if (line.size() < 2) throw std::invalid_argument("the scene's IMA centerline has under 2 points");
  metrics::HeatMapFrame f;
  // The fascia lies tangent to the wall over the IMA's middle: its normal is the wall's there.
  const Vec3 n = (layout.fascia_pose.rotation * Vec3::UnitY()).normalized();
  const Vec3 along = line.back() - line.front();
  f.origin = layout.ima_midpoint;
  f.u = (along - along.dot(n) * n).normalized();
  f.v = n.cross(f.u).normalized();
  f.centerline = line;

  const tissue::TissueWorld& w = s.scene.patch.world;
  const std::vector<Vec3>& rest = w.state.particles.rest_position;
  const tissue::MeshObject& fascia = w.meshes[s.scene.patch.fascia];
  metrics::HeatMapOutline fascia_outline;
  fascia_outline.name = "fascia";
  fascia_outline.rgb = kFasciaRgb;
  for (std::uint32_t v : longest_boundary_loop(fascia.triangles))
    fascia_outline.points.push_back(rest[fascia.first_particle + v]);
  if (!fascia_outline.points.empty()) f.outlines.push_back(std::move(fascia_outline));

  std::vector<Vec3> fat;
  for (const std::uint32_t set : {s.scene.patch.ima_fat, s.scene.patch.fascia_fat}) {
    const tissue::StrandSet& strands = w.strands[set];
    for (std::uint32_t i = 0; i < strands.particle_count(); ++i)
      fat.push_back(rest[strands.first_particle + i]);
  }
  if (!fat.empty()) f.outlines.push_back(hull_outline(f, "fat", kFatRgb, fat));
  if (!s.scene.heart.reference.empty())
    f.outlines.push_back(hull_outline(f, "heart", kHeartRgb, s.scene.heart.reference));
  metrics::check_heat_map_frame(f, "the session's heat map frame");
  return f;
}

}  // namespace imasim::console
