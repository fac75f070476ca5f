#include "tissue/heart_field.hpp"

#include <cmath>
#include <limits>

#include "geometry/closest_point.hpp"
#include "geometry/vertex_normals.hpp"

namespace imasim::tissue {

namespace {

// The heart's surface moves less than 0.2 mm per 5 ms step (30 mm/s at peak ejection) and
// particles are put back outside every step, so none can be found deeper than a few tenths of a
// millimetre: a 2 mm search (kHeartStepSearch) over a 5 mm grid suffices.
constexpr Real kColliderCell = Real(0.005);

void refresh_collider(HeartField& h) {
  const auto& tris = h.model.topology.triangles;
  geometry::compute_vertex_normals(h.current, tris, h.normals);
  for (std::size_t t = 0; t < tris.size(); ++t) {
    h.boxes[t] =
        geometry::triangle_box(h.current[tris[t][0]], h.current[tris[t][1]], h.current[tris[t][2]]);
  }
  h.grid.rebuild(h.boxes, kColliderCell);
}

}  // namespace

HeartField make_heart_field(const HeartModel& model, const HeartPlayback& playback) {
  HeartField h;
  h.model = model;
  h.playback = playback;
  interpolate_heart(model, playback.static_phase, h.reference);
  h.phase = playback.phase_at(0);
  interpolate_heart(model, h.phase, h.current);
  h.normals.resize(h.current.size());
  h.boxes.resize(model.topology.triangles.size());
  refresh_collider(h);
  // The heart changes its extent as it beats: keep room for the grid's largest rebuild.
  h.grid.reserve_headroom(Real(3));
  h.visited.assign(model.topology.triangles.size(), 0u);
  return h;
}

void add_heart_anchors(HeartField& h, TissueWorld& world, const std::vector<std::uint32_t>& meshes,
                       const std::vector<std::uint32_t>& strand_sets) {
  const physics::Particles& P = world.state.particles;
  std::vector<std::uint32_t> particles;
  for (std::uint32_t m : meshes) {
    for (std::uint32_t k = 0; k < world.meshes[m].particle_count; ++k) {
      particles.push_back(world.meshes[m].first_particle + k);
    }
  }
  for (std::uint32_t s : strand_sets) {
    const StrandSet& set = world.strands[s];
    for (std::uint32_t i = 0; i < set.strand_count; ++i) {
      for (std::uint32_t k = 1; k < set.segments; ++k)
        particles.push_back(set.particle(i, k));
    }
  }
  std::vector<geometry::Box> vertex_boxes;
  for (const Vec3& x : h.reference)
    vertex_boxes.emplace_back(x);
  const geometry::UniformGrid vertices(vertex_boxes, Real(0.01));
  std::vector<std::uint32_t> visited;
  std::uint32_t stamp = 0;
  for (std::uint32_t i : particles) {
    // Nearest heart vertex: search growing boxes until one is found.
    std::uint32_t best = 0;
    Real best_d2 = std::numeric_limits<Real>::infinity();
    for (Real r = Real(0.01); !std::isfinite(best_d2); r *= 2) {
      const Vec3& x = P.rest_position[i];
      vertices.visit(geometry::Box(x - Vec3::Constant(r), x + Vec3::Constant(r)), visited, stamp,
                     [&](std::uint32_t v) {
                       const Real d2 = (h.reference[v] - x).squaredNorm();
                       if (d2 < best_d2 || (d2 == best_d2 && v < best)) best_d2 = d2, best = v;
                     });
    }
    h.anchors.push_back({i, best, std::exp(-std::sqrt(best_d2) / h.attenuation_length)});
  }
  if (world.reference.size() != P.size()) world.reference = P.rest_position;
}

void advance_heart(HeartField& h, TissueWorld& world, double time_s) {
  h.phase = h.playback.phase_at(time_s);
  interpolate_heart(h.model, h.phase, h.current);
  refresh_collider(h);
  physics::Particles& P = world.state.particles;
  for (const HeartField::Anchor& a : h.anchors) {
    const Vec3 moved = P.rest_position[a.particle] +
                       a.weight * (h.current[a.heart_vertex] - h.reference[a.heart_vertex]);
    world.reference[a.particle] = moved;
    if (P.is_fixed(a.particle)) P.position[a.particle] = moved;
  }
}

Real heart_signed_distance(HeartField& h, const Vec3& p, Real search) {
  const auto& tris = h.model.topology.triangles;
  Real best_d2 = search * search;
  Real signed_distance = std::numeric_limits<Real>::infinity();
  std::uint32_t best_t = 0;
  h.grid.visit(geometry::Box(p - Vec3::Constant(search), p + Vec3::Constant(search)), h.visited,
               h.stamp, [&](std::uint32_t t) {
                 const auto& tri = tris[t];
                 const geometry::TrianglePoint q = geometry::closest_point_on_triangle(
                     p, h.current[tri[0]], h.current[tri[1]], h.current[tri[2]]);
                 if (q.distance2 > best_d2 || (q.distance2 == best_d2 && t > best_t)) return;
                 best_d2 = q.distance2;
                 best_t = t;
                 const Vec3 n = q.bary[0] * h.normals[tri[0]] + q.bary[1] * h.normals[tri[1]] +
                                q.bary[2] * h.normals[tri[2]];
                 const Real side = (p - q.point).dot(n);
                 signed_distance = side < 0 ? -std::sqrt(q.distance2) : std::sqrt(q.distance2);
               });
  return signed_distance;
}

std::uint32_t collide_with_heart(HeartField& h, physics::Particles& P,
                                 std::span<const Vec3> previous, Real min_search) {
  geometry::Box bounds;
  for (const Vec3& x : h.current)
    bounds.extend(x);
  const auto& tris = h.model.topology.triangles;
  std::uint32_t contacts = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.inverse_mass[i] == 0) continue;
    const Vec3 p = P.position[i];
    const Real search = min_search + (p - previous[i]).norm();
    if (bounds.exteriorDistance(p) > search) continue;
    Real best_d2 = search * search;
    std::uint32_t best_t = std::numeric_limits<std::uint32_t>::max();
    geometry::TrianglePoint best;
    h.grid.visit(geometry::Box(p - Vec3::Constant(search), p + Vec3::Constant(search)), h.visited,
                 h.stamp, [&](std::uint32_t t) {
                   const auto& tri = tris[t];
                   const geometry::TrianglePoint q = geometry::closest_point_on_triangle(
                       p, h.current[tri[0]], h.current[tri[1]], h.current[tri[2]]);
                   if (q.distance2 < best_d2 || (q.distance2 == best_d2 && t < best_t)) {
                     best_d2 = q.distance2, best_t = t, best = q;
                   }
                 });
    if (best_t == std::numeric_limits<std::uint32_t>::max()) continue;
    const auto& tri = tris[best_t];
    Vec3 n = best.bary[0] * h.normals[tri[0]] + best.bary[1] * h.normals[tri[1]] +
             best.bary[2] * h.normals[tri[2]];
    if (!(n.norm() > 0)) continue;
    n.normalize();
    if ((p - best.point).dot(n) >= h.margin) continue;  // outside, clear of the margin
    P.position[i] = best.point + h.margin * n;
    const Real vn = P.velocity[i].dot(n);
    if (vn < 0) P.velocity[i] -= vn * n;
    ++contacts;
  }
  h.last_contacts = contacts;
  return contacts;
}

}  // namespace imasim::tissue
