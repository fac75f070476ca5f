#include "tissue/heart_field.hpp"

#include <algorithm>
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

// Below 1 by far more than the rounding of a closest point (see nearest_per_component).
constexpr Real kBoxSlack = Real(1) - Real(1e-9);

// How far the grid's boxes reach past their triangles', so that the grid serves while the heart
// travels less (unit: m): a beat's fastest motion is about 0.2 mm a step.
constexpr Real kGridSlack = Real(0.001);

// The normals and the triangles' boxes now; the grid rebuilt once the heart has travelled its
// slack since it was built. Until then every triangle lies inside the box it was filed under (no
// point of it has moved farther than the travel), so a query visits every triangle its box
// reaches, among others that the exact boxes then skip: the same answers.
void refresh_collider(HeartField& h) {
  const auto& tris = h.model.topology.triangles;
  geometry::compute_vertex_normals(h.current, tris, h.normals);
  for (std::size_t t = 0; t < tris.size(); ++t) {
    h.boxes[t] =
        geometry::triangle_box(h.current[tris[t][0]], h.current[tris[t][1]], h.current[tris[t][2]]);
  }
  const Real travelled = h.clearance.travel - h.grid_travel_at;
  if (h.grid_travel_at >= 0 && travelled < kGridSlack) return;
  h.grid_boxes.resize(h.boxes.size());  // sized at set-up: no allocation
  for (std::size_t t = 0; t < h.boxes.size(); ++t) {
    h.grid_boxes[t] = geometry::Box(h.boxes[t].min() - Vec3::Constant(kGridSlack),
                                    h.boxes[t].max() + Vec3::Constant(kGridSlack));
  }
  h.grid.rebuild(h.grid_boxes, kColliderCell);
  h.grid_travel_at = h.clearance.travel;
}

}  // namespace

HeartField make_heart_field(const HeartModel& model, const HeartPlayback& playback) {
  HeartField h;
  h.model = model;
  h.playback = playback;
  interpolate_heart(model, playback.static_phase, h.reference);
  h.phase = playback.phase_at(0);
  interpolate_heart(model, h.phase, h.current);
  h.previous = h.current;
  h.normals.resize(h.current.size());
  h.boxes.resize(model.topology.triangles.size());
  refresh_collider(h);
  // The heart changes its extent as it beats: keep room for the grid's largest rebuild.
  h.grid.reserve_headroom(Real(3));
  h.visited.assign(model.topology.triangles.size(), 0u);
  h.nearest.resize(model.component_triangle_start.size() - 1);
  h.triangle_component.resize(model.topology.triangles.size());
  for (std::uint32_t c = 0; c + 1 < model.component_triangle_start.size(); ++c) {
    for (std::uint32_t t = model.component_triangle_start[c];
         t < model.component_triangle_start[c + 1]; ++t)
      h.triangle_component[t] = c;
  }
  return h;
}

void add_heart_anchors(HeartField& h, TissueWorld& world, const std::vector<std::uint32_t>& meshes,
                       const std::vector<std::uint32_t>& strand_sets) {
  const physics::Particles& P = world.state.particles;
  std::vector<std::uint32_t> particles;
  std::size_t spare = 0;  // vertices cutting may add to these meshes, anchored as they come
  for (std::uint32_t m : meshes) {
    const MeshObject& mesh = world.meshes[m];
    for (std::uint32_t k = 0; k < mesh.particle_count; ++k)
      particles.push_back(mesh.first_particle + k);
    spare += mesh.particle_capacity > mesh.particle_count
                 ? mesh.particle_capacity - mesh.particle_count
                 : 0;
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
  h.anchors.reserve(h.anchors.size() + particles.size() + spare);
  h.anchor_of.resize(P.size(), HeartField::kNone);
  for (std::uint32_t i : particles) {
    // Nearest heart vertex: search growing boxes until one is found, then once more in the box
    // that holds the ball through the one found. (The first find can be any vertex of the box:
    // outside the grid's bounds the box is clamped to its border cells.)
    std::uint32_t best = 0;
    Real best_d2 = std::numeric_limits<Real>::infinity();
    const Vec3& x = P.rest_position[i];
    auto search = [&](Real r) {
      vertices.visit(geometry::Box(x - Vec3::Constant(r), x + Vec3::Constant(r)), visited, stamp,
                     [&](std::uint32_t v) {
                       const Real d2 = (h.reference[v] - x).squaredNorm();
                       if (d2 < best_d2 || (d2 == best_d2 && v < best)) best_d2 = d2, best = v;
                     });
    };
    Real r = Real(0.01);
    for (; !std::isfinite(best_d2); r *= 2)
      search(r);
    if (std::sqrt(best_d2) > r / 2) search(std::sqrt(best_d2));
    h.anchor_of[i] = static_cast<std::uint32_t>(h.anchors.size());
    h.anchors.push_back({i, best, std::exp(-std::sqrt(best_d2) / h.attenuation_length)});
  }
  if (world.reference.size() != P.size()) world.reference = P.rest_position;
}

void anchor_new_vertices(HeartField& h, TissueWorld& world, std::uint32_t mesh,
                         std::uint32_t first_new_vertex, std::span<const NewVertex> vertices) {
  physics::Particles& P = world.state.particles;
  const std::uint32_t first = world.meshes[mesh].first_particle;
  auto anchor_index = [&](std::uint32_t particle) {
    return particle < h.anchor_of.size() ? h.anchor_of[particle] : HeartField::kNone;
  };
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    const NewVertex& nv = vertices[k];
    const std::uint32_t i = first + first_new_vertex + static_cast<std::uint32_t>(k);
    const std::uint32_t ka = anchor_index(first + nv.a), kb = anchor_index(first + nv.b);
    if (ka == HeartField::kNone || kb == HeartField::kNone) continue;  // not an anchored mesh
    const HeartField::Anchor a = h.anchors[ka], b = h.anchors[kb];
    // The nearer parent's heart vertex (a fresh nearest search would cost set-up time); the
    // weight as the position, so a copy (t = 0) moves exactly as its parent.
    const std::uint32_t vertex = nv.t <= Real(0.5) ? a.heart_vertex : b.heart_vertex;
    const Real weight = (1 - nv.t) * a.weight + nv.t * b.weight;
    if (h.anchor_of.size() <= i) h.anchor_of.resize(P.size(), HeartField::kNone);
    h.anchor_of[i] = static_cast<std::uint32_t>(h.anchors.size());
    h.anchors.push_back({i, vertex, weight});
    // Where the drive puts it now, as advance_heart does.
    const Vec3 moved = P.rest_position[i] + weight * (h.current[vertex] - h.reference[vertex]);
    if (world.reference.size() == P.size()) world.reference[i] = moved;
    if (P.is_fixed(i)) P.position[i] = moved;
  }
}

void advance_heart(HeartField& h, TissueWorld& world, double time_s) {
  h.phase = h.playback.phase_at(time_s);
  h.previous = h.current;  // sized at set-up: no allocation
  interpolate_heart(h.model, h.phase, h.current);
  Real farthest = 0;  // no point of the surface moved farther (heart_clearance.hpp)
  for (std::size_t v = 0; v < h.current.size(); ++v)
    farthest = std::max(farthest, (h.current[v] - h.previous[v]).norm());
  h.clearance.travel += farthest;
  refresh_collider(h);
  physics::Particles& P = world.state.particles;
  for (const HeartField::Anchor& a : h.anchors) {
    const Vec3 moved = P.rest_position[a.particle] +
                       a.weight * (h.current[a.heart_vertex] - h.reference[a.heart_vertex]);
    world.reference[a.particle] = moved;
    if (P.is_fixed(a.particle)) P.position[a.particle] = moved;
  }
}

namespace {

// nearest_per_component's search, reaching `reach` >= search: what lies between search and reach
// is found but not reported, and bounds the distance to the whole surface. Returns that bound:
// no triangle nearer to p (a rounding's slack under it).
// nearest, visited, stamp: the query's scratch (the field's own, or a part's).
Real search_heart(HeartField& h, std::vector<HeartField::Nearest>& nearest,
                  std::vector<std::uint32_t>& visited, std::uint32_t& stamp, const Vec3& p,
                  Real search, Real reach) {
  const auto& tris = h.model.topology.triangles;
  for (HeartField::Nearest& n : nearest)
    n = HeartField::Nearest{};
  auto consider = [&](std::uint32_t t) {
    HeartField::Nearest& best = nearest[h.triangle_component[t]];
    // A triangle's distance is at least its box's: skip the closest-point computation for
    // triangles whose box is beyond the reach or the component's best so far. The slack
    // keeps the skip conservative under rounding, so the answer is the same.
    const Real box2 = h.boxes[t].squaredExteriorDistance(p) * kBoxSlack;
    if (box2 > reach * reach || box2 > best.distance2) return;
    const auto& tri = tris[t];
    const geometry::TrianglePoint q = geometry::closest_point_on_triangle(
        p, h.current[tri[0]], h.current[tri[1]], h.current[tri[2]]);
    if (q.distance2 > reach * reach) return;
    if (q.distance2 > best.distance2 || (q.distance2 == best.distance2 && t > best.triangle))
      return;
    best.distance2 = q.distance2;
    best.triangle = t;
    best.point = q.point;
    best.normal = q.bary[0] * h.normals[tri[0]] + q.bary[1] * h.normals[tri[1]] +
                  q.bary[2] * h.normals[tri[2]];
  };
  h.grid.visit(geometry::Box(p - Vec3::Constant(reach), p + Vec3::Constant(reach)), visited, stamp,
               consider);
  // Every triangle is beyond the reach (not visited, or its box is) or no nearer than its
  // component's best.
  Real clear2 = reach * reach;
  for (HeartField::Nearest& n : nearest) {
    clear2 = std::min(clear2, n.distance2);
    if (n.triangle == HeartField::kNone || n.distance2 > search * search ||
        !(n.normal.norm() > 0)) {
      n = HeartField::Nearest{};
      continue;
    }
    n.normal.normalize();
    const Real d = std::sqrt(n.distance2);
    n.signed_distance = (p - n.point).dot(n.normal) < 0 ? -d : d;
  }
  return std::sqrt(clear2) * kBoxSlack;
}

// What the clearance proves of particle's query at p, or else its search (heart_clearance.hpp);
// the answer in nearest; counts the query as searched or skipped. The clearance is sized.
void clearance_query(HeartField& h, std::vector<HeartField::Nearest>& nearest,
                     std::vector<std::uint32_t>& visited, std::uint32_t& stamp,
                     std::uint64_t& searched, std::uint64_t& skipped, std::uint32_t particle,
                     const Vec3& p, Real search) {
  HeartClearance& c = h.clearance;
  const Real known = c.distance[particle];
  if (known - (p - c.from[particle]).norm() - (c.travel - c.travel_at[particle]) > search) {
    ++skipped;
    for (HeartField::Nearest& n : nearest)
      n = HeartField::Nearest{};
    return;
  }
  ++searched;
  // A particle near the heart last time searches as far as asked (it is likely near still); one
  // clear of it, or new, farther.
  const Real reach = known < 0 || known >= search ? search + c.reach : search;
  c.distance[particle] = search_heart(h, nearest, visited, stamp, p, search, reach);
  c.from[particle] = p;
  c.travel_at[particle] = c.travel;
}

void size_clearance(HeartClearance& c, std::size_t particles) {
  if (c.distance.size() == particles) return;
  c.distance.assign(particles, Real(-1));  // once, at the first step
  c.from.assign(particles, Vec3::Zero());
  c.travel_at.assign(particles, Real(0));
}

}  // namespace

// Nearest point of each component of the heart's surface to p within `search`, the side of p
// (signed distance, negative inside) and the surface normal there. The heart is a union of
// closed surfaces (LV, RV) that may overlap; p is inside the heart when it is inside any.
void nearest_per_component(HeartField& h, const Vec3& p, Real search) {
  search_heart(h, h.nearest, h.visited, h.stamp, p, search, search);
}

void nearest_per_component_of_particle(HeartField& h, std::uint32_t particle, std::size_t particles,
                                       const Vec3& p, Real search) {
  size_clearance(h.clearance, particles);
  clearance_query(h, h.nearest, h.visited, h.stamp, h.clearance.searched, h.clearance.skipped,
                  particle, p, search);
}

void nearest_per_component_of_particle(HeartField& h, HeartField::PartQuery& q,
                                       std::uint32_t particle, const Vec3& p, Real search) {
  clearance_query(h, q.nearest, q.visited, q.stamp, q.searched, q.skipped, particle, p, search);
}

void prepare_heart_queries(HeartField& h, std::size_t particles, const physics::Executor& exec) {
  size_clearance(h.clearance, particles);
  if (h.part_queries.size() < exec.parts()) h.part_queries.resize(exec.parts());
  for (HeartField::PartQuery& q : h.part_queries) {
    q.nearest.resize(h.nearest.size());
    q.searched = q.skipped = 0;
    q.put_out = 0;
  }
}

void finish_heart_queries(HeartField& h) {
  for (HeartField::PartQuery& q : h.part_queries) {
    h.clearance.searched += q.searched;
    h.clearance.skipped += q.skipped;
    q.searched = q.skipped = 0;
    q.put_out = 0;
  }
}

Real heart_signed_distance(HeartField& h, const Vec3& p, Real search) {
  nearest_per_component(h, p, search);
  // Inside any component: as deep as the deepest; outside all: the distance to the nearest.
  Real inside = 0, outside = std::numeric_limits<Real>::infinity();
  for (const HeartField::Nearest& n : h.nearest) {
    if (n.triangle == HeartField::kNone) continue;
    if (n.signed_distance < 0)
      inside = std::min(inside, n.signed_distance);
    else
      outside = std::min(outside, n.signed_distance);
  }
  return inside < 0 ? inside : outside;
}

Vec3 heart_surface_velocity(HeartField& h, const Vec3& p, Real search) {
  const Real rate = h.playback.cycles_per_second();  // (unit: 1/s)
  if (!(rate > 0)) return Vec3::Zero();
  nearest_per_component(h, p, search);
  const HeartField::Nearest* best = nullptr;
  for (const HeartField::Nearest& n : h.nearest)
    if (n.triangle != HeartField::kNone && (!best || n.distance2 < best->distance2)) best = &n;
  if (!best) return Vec3::Zero();
  const auto& tri = h.model.topology.triangles[best->triangle];
  const geometry::TrianglePoint q = geometry::closest_point_on_triangle(
      p, h.current[tri[0]], h.current[tri[1]], h.current[tri[2]]);
  Vec3 v = Vec3::Zero();
  for (std::size_t k = 0; k < 3; ++k)
    v += q.bary[k] * heart_vertex_rate(h.model, h.phase, tri[k]);
  return rate * v;
}

namespace {

// Particles put out of the heart per chunk of a parallel pass.
constexpr std::size_t kHeartParticleChunk = 256;

}  // namespace

std::uint32_t collide_with_heart(HeartField& h, physics::Particles& P,
                                 std::span<const Vec3> previous, const physics::Executor& exec,
                                 Real min_search, Real inside) {
  geometry::Box bounds;
  for (const Vec3& x : h.current)
    bounds.extend(x);
  prepare_heart_queries(h, P.size(), exec);
  std::vector<HeartField::PartQuery>& parts = h.part_queries;
  exec.for_chunks_in_parts(
      P.size(), kHeartParticleChunk, [&](std::size_t part, std::size_t begin, std::size_t end) {
        HeartField::PartQuery& q = parts[part];
        for (std::size_t i = begin; i < end; ++i) {
          if (P.inverse_mass[i] == 0) continue;
          const Real search = min_search + (P.position[i] - previous[i]).norm();
          if (bounds.exteriorDistance(P.position[i]) > search) continue;
          // Out of the component p is deepest in, onto its surface plus the margin; where
          // components overlap that point can lie inside another, so look again (a few passes reach
          // the crease between them).
          bool moved = false;
          for (int pass = 0; pass < kHeartCollisionPasses; ++pass) {
            nearest_per_component_of_particle(h, q, static_cast<std::uint32_t>(i), P.position[i],
                                              search);
            const HeartField::Nearest* deepest = nullptr;
            for (const HeartField::Nearest& n : q.nearest) {
              if (n.triangle == HeartField::kNone || n.signed_distance >= h.margin - inside)
                continue;
              if (deepest == nullptr || n.signed_distance < deepest->signed_distance) deepest = &n;
            }
            if (deepest == nullptr) break;
            P.position[i] = deepest->point + h.margin * deepest->normal;
            const Real vn = P.velocity[i].dot(deepest->normal);
            if (vn < 0) P.velocity[i] -= vn * deepest->normal;
            moved = true;
          }
          q.put_out += moved ? 1 : 0;
        }
      });
  std::uint32_t contacts = 0;
  for (const HeartField::PartQuery& q : parts)
    contacts += q.put_out;
  finish_heart_queries(h);
  h.last_contacts = contacts;
  return contacts;
}

std::uint32_t collide_with_heart(HeartField& h, physics::Particles& P,
                                 std::span<const Vec3> previous, Real min_search, Real inside) {
  const physics::Executor serial(1);
  return collide_with_heart(h, P, previous, serial, min_search, inside);
}

}  // namespace imasim::tissue
