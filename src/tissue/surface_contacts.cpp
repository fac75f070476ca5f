#include "tissue/surface_contacts.hpp"

#include "geometry/closest_point.hpp"

namespace imasim::tissue {

namespace {

constexpr std::size_t kHeartContactChunk = 256;  // particles a chunk of the parallel gathering

}  // namespace

void gather_heart_contacts(HeartField& h, const physics::Particles& P, Real dt,
                           const SurfaceContactParams& params, physics::ContactSet& out,
                           const physics::Executor& exec) {
  geometry::Box bounds;
  for (std::size_t v = 0; v < h.current.size(); ++v) {
    bounds.extend(h.current[v]);
    bounds.extend(h.previous[v]);
  }
  const auto& tris = h.model.topology.triangles;
  prepare_heart_queries(h, P.size(), exec);
  auto gather = [&](std::size_t part, std::size_t begin, std::size_t end,
                    std::vector<physics::ContactRow>& rows) {
    HeartField::PartQuery& query = h.part_queries[part];
    for (std::size_t k = begin; k < end; ++k) {
      if (P.inverse_mass[k] == 0) continue;
      const Vec3 probe = P.position[k] + dt * P.velocity[k];
      const Real search = params.search + h.margin + dt * P.velocity[k].norm();
      if (bounds.exteriorDistance(probe) > search) continue;
      nearest_per_component_of_particle(h, query, static_cast<std::uint32_t>(k), probe, search);
      for (const HeartField::Nearest& n : query.nearest) {
        if (n.triangle == HeartField::kNone || n.signed_distance > search) continue;
        const auto& t = tris[n.triangle];
        const geometry::TrianglePoint q = geometry::closest_point_on_triangle(
            probe, h.current[t[0]], h.current[t[1]], h.current[t[2]]);
        physics::ContactRow c;
        c.particle = static_cast<std::uint32_t>(k);
        c.tag = kHeartContact;
        c.point1 = q.point;
        c.point0 = q.bary[0] * h.previous[t[0]] + q.bary[1] * h.previous[t[1]] +
                   q.bary[2] * h.previous[t[2]];
        c.normal = n.normal;
        c.margin = h.margin;
        c.static_friction = params.heart_static_friction;
        c.kinetic_friction = params.heart_kinetic_friction;
        rows.push_back(c);
      }
    }
  };
  // Room for a row per component (ventricle) a particle.
  h.contact_chunks.gather(exec, P.size(), kHeartContactChunk, h.nearest.size(), out.rows, gather);
  finish_heart_queries(h);
}

void gather_heart_contacts(HeartField& h, const physics::Particles& P, Real dt,
                           const SurfaceContactParams& params, physics::ContactSet& out) {
  const physics::Executor serial(1);
  gather_heart_contacts(h, P, dt, params, out, serial);
}

namespace {

constexpr std::size_t kSurfaceContactChunk = 512;  // particles a chunk of the wall's and floor's

// The chest wall's row for particle k: false where k is fixed or out of reach. axis: the wall's,
// normalised.
bool wall_row(const geometry::CylinderPatchSpec& wall, const Vec3& axis,
              const physics::Particles& P, std::size_t k, Real dt,
              const SurfaceContactParams& params, physics::ContactRow& c) {
  if (P.inverse_mass[k] == 0) return false;
  const Vec3 probe = P.position[k] + dt * P.velocity[k];
  const Vec3 r = probe - wall.origin;
  const Vec3 radial = r - r.dot(axis) * axis;
  const Real distance = radial.norm();
  const Real search = params.search + dt * P.velocity[k].norm();
  if (distance < wall.radius - search || !(distance > 0)) return false;
  const Vec3 outward = radial / distance;
  c = physics::ContactRow{};
  c.particle = static_cast<std::uint32_t>(k);
  c.tag = kWallContact;
  c.point0 = c.point1 = wall.origin + r.dot(axis) * axis + wall.radius * outward;
  c.normal = -outward;  // the cavity's side
  c.static_friction = params.wall_static_friction;
  c.kinetic_friction = params.wall_kinetic_friction;
  return true;
}

// The cavity floor's row for particle k: false where k is fixed or out of reach.
bool floor_row(Real floor_y, const physics::Particles& P, std::size_t k, Real dt,
               const SurfaceContactParams& params, physics::ContactRow& c) {
  if (P.inverse_mass[k] == 0) return false;
  const Vec3 probe = P.position[k] + dt * P.velocity[k];
  if (probe.y() - floor_y > params.search + dt * P.velocity[k].norm()) return false;
  c = physics::ContactRow{};
  c.particle = static_cast<std::uint32_t>(k);
  c.tag = kFloorContact;
  c.point0 = c.point1 = Vec3(probe.x(), floor_y, probe.z());
  c.normal = Vec3::UnitY();
  c.static_friction = params.floor_static_friction;
  c.kinetic_friction = params.floor_kinetic_friction;
  return true;
}

}  // namespace

void gather_wall_contacts(const geometry::CylinderPatchSpec& wall, const physics::Particles& P,
                          Real dt, const SurfaceContactParams& params, physics::ContactSet& out) {
  const Vec3 axis = wall.axis.normalized();
  physics::ContactRow c;
  for (std::size_t k = 0; k < P.size(); ++k)
    if (wall_row(wall, axis, P, k, dt, params, c)) out.rows.push_back(c);
}

void gather_floor_contacts(Real floor_y, const physics::Particles& P, Real dt,
                           const SurfaceContactParams& params, physics::ContactSet& out) {
  physics::ContactRow c;
  for (std::size_t k = 0; k < P.size(); ++k)
    if (floor_row(floor_y, P, k, dt, params, c)) out.rows.push_back(c);
}

void gather_wall_and_floor_contacts(const geometry::CylinderPatchSpec& wall, Real floor_y,
                                    const physics::Particles& P, Real dt,
                                    const SurfaceContactParams& params, physics::ContactSet& out,
                                    const physics::Executor& exec, WallAndFloorChunks& chunks) {
  const Vec3 axis = wall.axis.normalized();
  using Rows = std::vector<physics::ContactRow>;
  chunks.wall.gather(exec, P.size(), kSurfaceContactChunk, 1, out.rows,
                     [&](std::size_t, std::size_t begin, std::size_t end, Rows& rows) {
                       physics::ContactRow c;
                       for (std::size_t k = begin; k < end; ++k)
                         if (wall_row(wall, axis, P, k, dt, params, c)) rows.push_back(c);
                     });
  chunks.floor.gather(exec, P.size(), kSurfaceContactChunk, 1, out.rows,
                      [&](std::size_t, std::size_t begin, std::size_t end, Rows& rows) {
                        physics::ContactRow c;
                        for (std::size_t k = begin; k < end; ++k)
                          if (floor_row(floor_y, P, k, dt, params, c)) rows.push_back(c);
                      });
}

void drop_held_rows(physics::ContactSet& out, std::size_t first,
                    std::span<const std::uint8_t> held) {
  std::size_t kept = first;
  for (std::size_t k = first; k < out.rows.size(); ++k) {
    const std::uint32_t i = out.rows[k].particle;
    if (i < held.size() && held[i]) continue;
    out.rows[kept++] = out.rows[k];
  }
  out.rows.resize(kept);
}

}  // namespace imasim::tissue
