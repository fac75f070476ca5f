#include "surgery/tool_contact.hpp"

#include "geometry/closest_point.hpp"
#include "math/validation_assert.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace imasim::surgery {

void translate_tool_geometry(ToolGeometry& tool, const Vec3& by) {
  for (Capsule& c : tool.capsules) {
    c.a += by;
    c.b += by;
  }
  for (OrientedBox& b : tool.boxes)
    b.pose.translation += by;
}

void make_tool_geometry(const InstrumentParams& params, const InstrumentState& state,
                        ToolGeometry& out) {
  const Pose tool = world_pose(params, state);
  const Vec3 hinge = tool.translation;
  const Vec3 f = tool.rotation.col(2);
  // resize keeps the capacity, so a geometry rebuilt every step allocates only the first time.
  out.capsules.resize(1);
  out.capsules[0] = Capsule{hinge - params.shaft_length * f, hinge, params.shaft_radius};
  out.boxes.resize(2);
  const Vec3 half(params.jaws.width / 2, kJawThickness / 2, params.jaws.length / 2);
  const Pose jaws[2] = {upper_jaw_pose(params, state), lower_jaw_pose(params, state)};
  for (int k = 0; k < 2; ++k) {
    OrientedBox& box = out.boxes[static_cast<std::size_t>(k)];
    box.pose.rotation = jaws[k].rotation;
    // Half-way from the hinge to the jaw's tip, along the jaw's own f.
    box.pose.translation = jaws[k].apply(Vec3(0, 0, params.jaws.length / 2));
    box.half_extents = half;
  }
  out.velocity = Vec3::Zero();
}

namespace {

// A unit vector perpendicular to the unit vector e: e crossed with the coordinate axis least
// aligned with it (a fixed choice, so the result is deterministic).
Vec3 perpendicular(const Vec3& e) {
  Eigen::Index least = 0;
  e.cwiseAbs().minCoeff(&least);
  return e.cross(Vec3::Unit(least)).normalized();
}

}  // namespace

SurfacePoint capsule_surface(const Capsule& c, const Vec3& x) {
  const Vec3 axis = c.b - c.a;
  const Real length2 = axis.squaredNorm();
  // Closest point on the segment; a degenerate segment is a sphere about a.
  const Vec3 centre = c.a + geometry::closest_segment_parameter(x, c.a, c.b) * axis;
  const Vec3 r = x - centre;
  const Real distance = r.norm();
  Vec3 normal;
  if (distance > 0)
    normal = r / distance;
  else if (length2 > 0)
    normal = perpendicular(axis / std::sqrt(length2));  // on the axis: any radial direction
  else
    normal = Vec3::UnitX();  // at a sphere's centre: any direction
  return {distance - c.radius, centre + c.radius * normal, normal};
}

SurfacePoint box_surface(const OrientedBox& box, const Vec3& x) {
  const Mat3& R = box.pose.rotation;
  const Vec3& h = box.half_extents;
  const Vec3 q = R.transpose() * (x - box.pose.translation);  // x in the box's frame
  const Vec3 clamped = q.cwiseMax(-h).cwiseMin(h);
  if (clamped != q) {
    // Outside: the closest point is the clamped one.
    const Vec3 d = q - clamped;
    const Real distance = d.norm();
    return {distance, box.pose.apply(clamped), R * (d / distance)};
  }
  // Inside (or on the surface): out through the nearest face.
  int axis = 0;
  Real depth = std::numeric_limits<Real>::infinity();
  for (int i = 0; i < 3; ++i) {
    const Real to_face = h[i] - std::abs(q[i]);
    if (to_face < depth) depth = to_face, axis = i;
  }
  const Real sign = q[axis] >= 0 ? Real(1) : Real(-1);
  Vec3 on_face = q;
  on_face[axis] = sign * h[axis];
  return {-depth, box.pose.apply(on_face), sign * R.col(axis)};
}

namespace {

// One contact: projects x out of the shape along the normal (XPBD against a kinematic body),
// then applies positional Coulomb friction relative to the tool. Returns the depth projected
// (0 when there is no contact).
Real project(const SurfacePoint& s, const ContactParams& params, Real w, Real alpha_tilde,
             const Vec3& start, const Vec3& tool_step, Vec3& x) {
  const Real depth = params.margin - s.distance;  // C, the penetration including the margin
  if (!(depth > 0)) return 0;
  const Real dlambda = depth / (w + alpha_tilde);
  const Real dn = w * dlambda;  // normal correction; the friction cone's bound (= depth if hard)
  x += dn * s.normal;
  // Slip relative to the tool this step, tangential part.
  const Vec3 dp = (x - start) - tool_step;
  const Vec3 dp_t = dp - dp.dot(s.normal) * s.normal;
  const Real slip = dp_t.norm();
  if (slip < params.static_friction * dn)
    x -= dp_t;  // static: the particle moves with the tool
  else if (slip > 0)
    x -= dp_t * std::min(params.kinetic_friction * dn / slip, Real(1));  // kinetic
  return depth;
}

}  // namespace

ContactSummary resolve_tool_contacts(physics::Particles& P, std::span<const Vec3> start,
                                     const ToolGeometry& tool, const ContactParams& params, Real dt,
                                     std::vector<ToolContact>& contacts) {
  IMASIM_ASSERT(start.size() >= P.size());
  IMASIM_ASSERT(dt > 0);
  contacts.clear();
  ContactSummary summary;
  if (tool.capsules.empty() && tool.boxes.empty()) return summary;

  // Broad phase: the tool's bounding box, grown by the margin; nothing outside it can touch.
  Vec3 lo = Vec3::Constant(std::numeric_limits<Real>::infinity());
  Vec3 hi = -lo;
  for (const Capsule& c : tool.capsules) {
    lo = lo.cwiseMin(c.a.cwiseMin(c.b) - Vec3::Constant(c.radius));
    hi = hi.cwiseMax(c.a.cwiseMax(c.b) + Vec3::Constant(c.radius));
  }
  for (const OrientedBox& b : tool.boxes) {
    const Vec3 extent = b.pose.rotation.cwiseAbs() * b.half_extents;
    lo = lo.cwiseMin(b.pose.translation - extent);
    hi = hi.cwiseMax(b.pose.translation + extent);
  }
  lo -= Vec3::Constant(params.margin);
  hi += Vec3::Constant(params.margin);

  const Real alpha_tilde = params.compliance / (dt * dt);
  const Vec3 tool_step = tool.velocity * dt;  // the tool's displacement this step (unit: m)
  auto record = [&](std::uint32_t i, const SurfacePoint& s, Real depth) {
    contacts.push_back({i, s.point, s.normal, depth});
    ++summary.count;
    if (s.distance < 0) ++summary.inside;
    const std::size_t object = std::min<std::size_t>(P.object[i], 7);
    ++summary.per_object[object];
    if (depth > summary.max_depth) {
      summary.max_depth = depth;
      summary.point = s.point;
      summary.normal = s.normal;
    }
  };

  for (std::size_t k = 0; k < P.size(); ++k) {
    const Real w = P.inverse_mass[k];
    if (w == 0) continue;  // fixed (or kinematic) particles are moved by whoever drives them
    Vec3& x = P.position[k];
    if ((x.array() < lo.array()).any() || (x.array() > hi.array()).any()) continue;
    const auto i = static_cast<std::uint32_t>(k);
    bool moved = false;
    for (const Capsule& c : tool.capsules) {
      const SurfacePoint s = capsule_surface(c, x);
      const Real depth = project(s, params, w, alpha_tilde, start[k], tool_step, x);
      if (depth > 0) {
        record(i, s, depth);
        moved = true;
      }
    }
    for (const OrientedBox& b : tool.boxes) {
      const SurfacePoint s = box_surface(b, x);
      const Real depth = project(s, params, w, alpha_tilde, start[k], tool_step, x);
      if (depth > 0) {
        record(i, s, depth);
        moved = true;
      }
    }
    // The physics step has already derived v = (x - x_start) / dt from the solver's positions;
    // contact moves x after that, so v is derived again from the final x. Otherwise the next
    // step would integrate a velocity that still points into the tool (and drags it back in),
    // and friction's carrying of the particle would be lost from v.
    if (moved) P.velocity[k] = (x - start[k]) / dt;
  }
  return summary;
}

namespace {

Pose inverse(const Pose& p) {
  const Mat3 rt = p.rotation.transpose();
  return {rt, -(rt * p.translation)};
}

}  // namespace

void gather_tool_contacts(const physics::Particles& P, const ToolGeometry& tool, const Pose& before,
                          const Pose& now, const ContactParams& params, Real dt, std::uint32_t tag,
                          physics::ContactSet& out, Real search) {
  if (tool.capsules.empty() && tool.boxes.empty()) return;
  const Pose back = before * inverse(now);  // a point of the tool now -> where it was
  // Broad phase: the tool's bounding box now and before, grown by the reach.
  Vec3 lo = Vec3::Constant(std::numeric_limits<Real>::infinity());
  Vec3 hi = -lo;
  auto extend = [&](const Vec3& x, const Vec3& r) {
    lo = lo.cwiseMin(x - r), hi = hi.cwiseMax(x + r);
  };
  for (const Capsule& c : tool.capsules) {
    for (const Vec3& x : {c.a, c.b, back.apply(c.a), back.apply(c.b)})
      extend(x, Vec3::Constant(c.radius));
  }
  for (const OrientedBox& b : tool.boxes) {
    const Vec3 extent = b.pose.rotation.cwiseAbs() * b.half_extents;
    extend(b.pose.translation, extent);
    extend(back.apply(b.pose.translation), extent);
  }
  const Real reach = params.margin + search;
  for (std::size_t k = 0; k < P.size(); ++k) {
    if (P.inverse_mass[k] == 0) continue;
    const Vec3 probe = P.position[k] + dt * P.velocity[k];
    const Real r = reach + dt * P.velocity[k].norm();
    if ((probe.array() < lo.array() - r).any() || (probe.array() > hi.array() + r).any()) continue;
    // One plane per particle and tool: that of the shape nearest it (two planes of one rigid tool
    // at an angle would only squeeze the particle between them).
    SurfacePoint nearest;
    nearest.distance = std::numeric_limits<Real>::infinity();
    for (const Capsule& c : tool.capsules) {
      const SurfacePoint s = capsule_surface(c, probe);
      if (s.distance < nearest.distance) nearest = s;
    }
    for (const OrientedBox& b : tool.boxes) {
      const SurfacePoint s = box_surface(b, probe);
      if (s.distance < nearest.distance) nearest = s;
    }
    auto add = [&](const SurfacePoint& s) {
      if (!(s.distance <= r)) return;
      IMASIM_ASSERT(std::abs(s.normal.norm() - 1) < Real(1e-9));
      physics::ContactRow c;
      c.particle = static_cast<std::uint32_t>(k);
      c.tag = tag;
      c.point1 = s.point;
      c.point0 = back.apply(s.point);
      c.normal = s.normal;
      c.margin = params.margin;
      c.static_friction = params.static_friction;
      c.kinetic_friction = params.kinetic_friction;
      out.rows.push_back(c);
    };
    add(nearest);
  }
}

ContactSummary summarize_tool_contacts(const physics::Particles& P,
                                       const physics::ContactSet& contacts, std::uint32_t tag) {
  ContactSummary summary;
  for (const physics::ContactRow& c : contacts.rows) {
    if (c.tag != tag || !(c.depth > 0)) continue;
    ++summary.count;
    ++summary.per_object[std::min<std::size_t>(P.object[c.particle], 7)];
    if (c.depth > summary.max_depth) {
      summary.max_depth = c.depth;
      summary.point = c.point1;
      summary.normal = c.normal;
    }
  }
  return summary;
}

}  // namespace imasim::surgery
