#include "session/surface_stop_rows.hpp"

#include "geometry/closest_point.hpp"
#include "session/surface_stops.hpp"

namespace imasim::session {
namespace {

using surgery::Tissue;

// Reach of the gathering beyond the clearance, the probe's own travel and the proxy's distance
// from the device (which the coupling may take it back over within the step) (unit: m).
constexpr Real kStopReach = Real(0.002);

// margin: kept between the point and the heart (unit: m).
void add_heart_rows(SurgicalSession& s, const Vec3& x0, const Vec3& x1, Real reach, Real margin,
                    std::uint32_t body, std::vector<physics::BodyStopRow>& out) {
  tissue::HeartField& h = s.scene.heart;
  tissue::nearest_per_component(h, x1, reach);
  const auto& tris = h.model.topology.triangles;
  for (const tissue::HeartField::Nearest& n : h.nearest) {
    if (n.triangle == tissue::HeartField::kNone || n.signed_distance > reach) continue;
    const auto& t = tris[n.triangle];
    const geometry::TrianglePoint q =
        geometry::closest_point_on_triangle(x1, h.current[t[0]], h.current[t[1]], h.current[t[2]]);
    physics::BodyStopRow r;
    r.body = body;
    r.tag = static_cast<std::uint32_t>(Tissue::heart);
    r.point0 = x0;
    r.point1 = x1;
    r.surface1 = q.point;
    r.surface0 =
        q.bary[0] * h.previous[t[0]] + q.bary[1] * h.previous[t[1]] + q.bary[2] * h.previous[t[2]];
    r.normal = n.normal;
    r.margin = margin;
    // The surface's eq. 18 mu: the spring carries its push, so the tool sticks while the device's
    // offset lies within the cone |o_t| <= mu |o_n|, whatever the coupling's k.
    r.static_friction = r.kinetic_friction =
        s.params.proxy.friction[static_cast<std::size_t>(Tissue::heart)];
    out.push_back(r);
  }
}

void add_wall_row(SurgicalSession& s, const Vec3& x0, const Vec3& x1, Real reach,
                  std::uint32_t body, std::vector<physics::BodyStopRow>& out) {
  const geometry::CylinderPatchSpec& wall = s.scene.layout.wall;
  const Vec3 axis = wall.axis.normalized();
  const Vec3 r = x1 - wall.origin;
  const Vec3 radial = r - r.dot(axis) * axis;
  const Real distance = radial.norm();
  if (distance < wall.radius - reach || !(distance > 0)) return;
  const Vec3 outward = radial / distance;
  physics::BodyStopRow row;
  row.body = body;
  row.tag = static_cast<std::uint32_t>(Tissue::chest_wall);
  row.point0 = x0;
  row.point1 = x1;
  row.surface0 = row.surface1 = wall.origin + r.dot(axis) * axis + wall.radius * outward;
  row.normal = -outward;  // the cavity's side
  row.margin = s.params.tool_clearance;
  row.static_friction = row.kinetic_friction =
      s.params.proxy.friction[static_cast<std::size_t>(Tissue::chest_wall)];
  out.push_back(row);
}

}  // namespace

void gather_surface_stop_rows(SurgicalSession& s, const Station& st, std::uint32_t body,
                              std::vector<physics::BodyStopRow>& out) {
  const Real electrode = s.params.cautery.electrode_length;
  // The probe points where the step ends, and the same points of the tool where it began (its
  // jaws' opening as it ends: they turn little within a step).
  const Pose& end = st.pose;
  const Pose& start = st.previous_pose;
  auto at_start = [&](const Vec3& x1) {
    return Vec3(start.translation +
                start.rotation * (end.rotation.transpose() * (x1 - end.translation)));
  };
  const Real travel = kStopReach + st.proxy.offset.norm();
  for (const Vec3& x1 : probe_points(st, electrode)) {
    const Vec3 x0 = at_start(x1);
    const Real reach = s.params.tool_clearance + travel + (x1 - x0).norm();
    add_heart_rows(s, x0, x1, reach, s.params.tool_clearance, body, out);
    add_wall_row(s, x0, x1, reach, body, out);
  }
  // The tissue the jaws hold keeps the heart's margin, as its contacts keep it: the jaws lying
  // across the heart's curve hold it inside the heart while their hinge and tips stay out, and the
  // hold, projected after the contacts, would win. So each held point stops the tool there.
  const tissue::HeartField& heart = s.scene.heart;
  for (const physics::BodyAttachmentRow& held : s.scene.patch.world.state.body_attachments) {
    if (held.body != body) continue;
    const Vec3 x0 = at_start(held.target);
    const Real reach = heart.margin + travel + (held.target - x0).norm();
    add_heart_rows(s, x0, held.target, reach, heart.margin, body, out);
  }
}

surgery::Tissue note_surface_stop_rows(Station& st, std::span<const physics::BodyStopRow> rows,
                                       const Vec3& carried, Real dt) {
  const physics::BodyStopRow* most = nullptr;
  for (const physics::BodyStopRow& r : rows) {
    if (!(r.normal_impulse > 0)) continue;
    const bool heart = r.tag == static_cast<std::uint32_t>(Tissue::heart);
    st.blocked_by_heart = st.blocked_by_heart || heart;
    st.blocked_by_wall = st.blocked_by_wall || !heart;
    if (most == nullptr || r.normal_impulse > most->normal_impulse) most = &r;
  }
  if (most == nullptr) return Tissue::none;
  Vec3 impulse = Vec3::Zero();  // the stopping surface's, on the tool (unit: N s)
  for (const physics::BodyStopRow& r : rows) {
    if (r.tag == most->tag && r.normal_impulse > 0)
      impulse += r.normal_impulse * r.normal + r.friction_impulse;
  }
  st.stop.tissue = static_cast<Tissue>(most->tag);
  st.stop.point = most->point1 + carried;
  // The proxy ends the step a little past the plane, by the spring's pull over the last
  // substep's coupling (k o h / c): the plane is where the tool meets the surface.
  st.stop.plane = most->surface1 + most->margin * most->normal;
  st.stop.normal = most->normal;
  st.stop.velocity = dt > 0 ? Vec3((most->surface1 - most->surface0) / dt) : Vec3::Zero();
  st.stop.force = dt > 0 && impulse.allFinite() ? Vec3(impulse / dt) : Vec3::Zero();
  return st.stop.tissue;
}

}  // namespace imasim::session
