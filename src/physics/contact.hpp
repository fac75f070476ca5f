#pragma once
// Contacts inside the solve (SPEC S1): a dynamic particle against a kinematic surface that moves
// during the step (the heart's wall, the chest wall, an instrument). Candidates are gathered once
// per step by whoever owns the surface (tissue/heart_contact.hpp, surgery/tool_contact.hpp): each
// is the surface's tangent plane near the particle, at its point on the surface at the step's
// start (point0) and end (point1), so the plane moves with the surface's own velocity there. In
// every substep, after the constraint sweeps of each iteration, the particle is kept on the
// plane's outer side plus a margin (a hard XPBD inequality against an infinitely heavy surface),
// with Coulomb friction in positional form (Mueller et al. 2020) against the surface's motion
// in that substep: the friction is what removes the slip while it stays within mu_s times the
// normal correction, else mu_k times it, both summed over the substep (friction_correction). A
// contact of a coarse object (ObjectParams::coarse) is projected in that object's substeps only. A
// row that names a proxy body (physics/proxy_body.hpp) is a two-body contact: the plane moves with
// the body's offset as well, and each correction, normal and tangential, is shared between particle
// and body by their inverse masses.
#include <cstdint>
#include <vector>

#include "math/types.hpp"
#include "physics/proxy_body.hpp"

namespace imasim::physics {

struct ContactRow {
  std::uint32_t particle = 0;
  std::uint32_t tag = 0;  // the caller's: which surface (for reports and events)
  Vec3 point0 = Vec3::Zero(), point1 = Vec3::Zero();  // surface point, step start / end (unit: m)
  Vec3 normal = Vec3::Zero();  // outward unit normal: the particle stays on its + side
  Real margin = 0;             // kept between surface and particle (unit: m)
  Real static_friction = 0, kinetic_friction = 0;  // mu_s, mu_k
  std::uint32_t body = kNoBody;  // the proxy body the surface belongs to, or none (kinematic)
  // A row on a body whose particle is kinematic for this step is idle, unless this is set: then
  // the particle is an obstacle and the body takes the whole correction (the implicit fascia,
  // solved before the XPBD step and held still in it, stops the instruments there).
  bool stops_body = false;
  // Results of the step: the deepest penetration corrected in its last substep and the normal
  // impulse over the step (sum of m dn / h; / dt gives the mean force).
  Real depth = 0;  // (unit: m)
  // How deep the particle was inside the surface when the step began: pushed out no faster than
  // SolverParams::push_out_speed (unit: m).
  Real start_depth = 0;
  // Within the substep: the normal correction so far and the tangential one friction made.
  Real substep_normal = 0;               // (unit: m)
  Vec3 substep_friction = Vec3::Zero();  // (unit: m)
  Real normal_impulse = 0;               // (unit: N s)
};

struct ContactSet {
  std::vector<ContactRow> rows;  // gathered for the next step, in a fixed order (determinism)

  void clear() { rows.clear(); }
  // Rows of one caller (tag range [first_tag, end_tag)): count of those in touch at the step's
  // end, the deepest one (or null).
  std::size_t touching(std::uint32_t first_tag, std::uint32_t end_tag) const;
};

// Coulomb's bound on friction over a whole substep, in which a row may be projected more than
// once (extra stretch sweeps, iterations): the row keeps the friction correction it has made so
// far in the substep (a vector, substep_friction) and the normal one (substep_normal). Each
// projection wants that friction plus the slip still left (slip_t: the tangential slip relative
// to the surface since the substep began); inside the static disc, mu_s times the normal
// correction, it gets it and the particle moves with the surface; outside, the friction is put on
// the kinetic disc's rim, mu_k times it, in the direction wanted (accumulated clamping, as
// impulse solvers clamp the friction they have accumulated). So over the substep friction never
// exceeds mu times the push, however many projections; against each projection's own dn, every
// projection after the first would let go, and against the accumulated dn without what friction
// has taken already, k projections could hold up to k mu. With one projection per substep this is
// the plain bound. Returns the correction to take off the particle's slip (unit: m). The fields
// it uses are a ContactRow's and a BodyStopRow's alike.
template <class Row>
inline Vec3 friction_correction(Row& c, Real dn, const Vec3& slip_t) {
  c.substep_normal += dn;
  const Vec3 wanted = c.substep_friction + slip_t;
  const Real size = wanted.norm();
  if (size <= c.static_friction * c.substep_normal) {  // static: it moves with the surface
    c.substep_friction = wanted;
    return slip_t;
  }
  const Real rim = c.kinetic_friction * c.substep_normal;
  const Vec3 next = size > rim ? Vec3((rim / size) * wanted) : wanted;
  const Vec3 removed = next - c.substep_friction;
  c.substep_friction = next;
  return removed;
}

// How far inside its surface a row may leave its particle at the end of a substep (unit: m): what
// is left of the step's starting overlap after pushing it out at push_out_speed until then
// (`pushed`, push_out_speed times the time since the step began).
inline Real overlap_allowance(const ContactRow& c, Real pushed) {
  return c.start_depth > pushed ? c.start_depth - pushed : Real(0);
}

// One projection (see above) against a kinematic surface. x_start: positions at the substep's
// start; tau0, tau1: the substep's start and end as fractions of the step; h: the substep's
// length (unit: s); allowance: overlap_allowance.
inline void project_contact(ContactRow& c, Vec3* p, const Vec3* x_start, const Real* w, Real tau0,
                            Real tau1, Real h, Real allowance = 0) {
  const Real wi = w[c.particle];
  if (wi == 0) return;
  Vec3& x = p[c.particle];
  const Vec3 motion = c.point1 - c.point0;
  const Vec3 q = c.point0 + tau1 * motion;
  const Real gap = c.normal.dot(x - q) - c.margin + allowance;
  if (!(gap < 0)) return;
  const Real dn = -gap;  // the normal correction (hard contact: all of it)
  x += dn * c.normal;
  c.depth = dn > c.depth ? dn : c.depth;
  c.normal_impulse += dn / (wi * h);
  // Slip relative to the surface over this substep, tangential part.
  const Vec3 slip = (x - x_start[c.particle]) - (tau1 - tau0) * motion;
  const Vec3 slip_t = slip - slip.dot(c.normal) * c.normal;
  x -= friction_correction(c, dn, slip_t);
}

// The same against a proxy body's surface: the plane is carried by the body's offset since the
// step began, and the particle (inverse mass w_i) and the body (w_b, proxy_inverse_mass) share
// each correction: the particle takes w_i / (w_i + w_b) of it, the body the rest, the other way.
// The friction bound compares the tangential and normal corrections before sharing, so it is the
// same Coulomb cone as against a kinematic surface.
// body_start: the body's offset at the substep's start.
inline void project_contact(ContactRow& c, Vec3* p, const Vec3* x_start, const Real* w,
                            ProxyBody& body, const Vec3& body_start, Real tau0, Real tau1, Real h,
                            Real allowance = 0) {
  const Real wi = w[c.particle];
  const Real wb = proxy_inverse_mass(body, h);
  if (wi == 0 && !(c.stops_body && wb > 0)) return;
  Vec3& x = p[c.particle];
  const Vec3 motion = c.point1 - c.point0;
  const Vec3 q = c.point0 + tau1 * motion + body.carried();
  const Real gap = c.normal.dot(x - q) - c.margin + allowance;
  if (!(gap < 0)) return;
  if (wi == 0) {  // an obstacle: the body moves out of it, frictionless
    const Vec3 pushed = gap * c.normal;
    body.offset += pushed;
    body.impulse += body.damping * pushed;
    c.depth = -gap > c.depth ? -gap : c.depth;
    return;
  }
  const Real share = wi / (wi + wb);  // the particle's part of each correction
  const Real dn = -gap;               // the whole normal correction
  x += (share * dn) * c.normal;
  const Vec3 pushed = ((1 - share) * dn) * c.normal;
  body.offset -= pushed;
  body.impulse -= body.damping * pushed;
  c.depth = dn > c.depth ? dn : c.depth;
  c.normal_impulse += share * dn / (wi * h);
  // Slip relative to the surface over this substep (its path and the body's own motion).
  const Vec3 surface = (tau1 - tau0) * motion + (body.offset - body_start);
  const Vec3 slip = (x - x_start[c.particle]) - surface;
  const Vec3 slip_t = slip - slip.dot(c.normal) * c.normal;
  const Vec3 removed = friction_correction(c, dn, slip_t);
  x -= share * removed;
  body.offset += (1 - share) * removed;
  body.impulse += body.damping * (1 - share) * removed;
}

// After the velocity update of a substep in which the contact pushed its particle out (depth >
// 0): the push resolved a penetration and must not also launch the particle. Its normal velocity
// relative to the surface is kept at or below zero (an inelastic contact, restitution 0, as the
// velocity pass of Mueller et al. 2020, 3.6). Without it a plane found a distance D above the
// particle at a step's start sends it off at D / h, a speed that grows as the substeps shrink
// (measured: the resting default scene gained energy above about 200 substeps and diverged at
// 400). inverse_dt: 1 / the step (the surface moves from point0 to point1 over it) (unit: 1/s).
// A body's surface moves with its offset too: `body_velocity` is that motion's rate over the
// substep (zero for a kinematic surface) (unit: m/s).
inline void remove_separating_velocity(const ContactRow& c, Vec3* v, Real inverse_dt,
                                       const Vec3& body_velocity = Vec3::Zero()) {
  if (!(c.depth > 0)) return;
  const Vec3 surface_velocity = (c.point1 - c.point0) * inverse_dt + body_velocity;
  const Real separating = c.normal.dot(v[c.particle] - surface_velocity);
  if (separating > 0) v[c.particle] -= separating * c.normal;
}

}  // namespace imasim::physics
