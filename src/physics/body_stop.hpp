#pragma once
// A proxy body stopped by a kinematic surface (the heart's wall, the chest wall): a
// point of the instrument (its hinge, a jaw's tip, the electrode) kept on the outer side of the
// surface's tangent plane plus a margin, inside the solve, the way a particle is kept out of it
// (contact.hpp), but with the body as the moving side. The surface is infinitely heavy, so the
// body takes the whole correction, normal and tangential; each correction delta of the body is
// the impulse c delta on the tool (proxy_body.hpp: it weighs c h over a substep h), so the
// surface's push enters the tool's force like the tissue's, and at rest it balances the
// coupling's spring: k (o - o_rest) = F_surface. Coulomb friction in positional form, with the
// same bound over the substep as a particle's contact (friction_correction), against the surface's
// own motion.
#include <cstdint>
#include <vector>

#include "math/types.hpp"
#include "physics/contact.hpp"
#include "physics/proxy_body.hpp"

namespace imasim::physics {

struct BodyStopRow {
  std::uint32_t body = 0;  // the proxy body (State::proxies)
  std::uint32_t tag = 0;   // the caller's: which surface
  // The body's point on its gathered path (without the offset the step carries it by) at the
  // step's start and end, and the surface's point at both (unit: m).
  Vec3 point0 = Vec3::Zero(), point1 = Vec3::Zero();
  Vec3 surface0 = Vec3::Zero(), surface1 = Vec3::Zero();
  Vec3 normal = Vec3::Zero();  // outward unit normal: the point stays on its + side
  Real margin = 0;             // kept between surface and point (unit: m)
  Real static_friction = 0, kinetic_friction = 0;  // mu_s, mu_k
  // Results of the step: the deepest correction in the last substep (unit: m) and the normal
  // impulse on the tool over the step (unit: N s; / dt gives the mean force).
  Real depth = 0;
  Real normal_impulse = 0;
  Vec3 friction_impulse = Vec3::Zero();  // the friction's on the tool over the step (unit: N s)
  // Within the substep: the normal correction so far and the tangential one friction made.
  Real substep_normal = 0;               // (unit: m)
  Vec3 substep_friction = Vec3::Zero();  // (unit: m)
};

// The point's gap to the plane at the substep's end (tau1, a fraction of the step), as the body
// stands now: negative inside (unit: m).
inline Real body_stop_gap(const BodyStopRow& r, const ProxyBody& body, Real tau1) {
  const Vec3 x = r.point0 + tau1 * (r.point1 - r.point0) + body.carried();
  const Vec3 q = r.surface0 + tau1 * (r.surface1 - r.surface0);
  return r.normal.dot(x - q) - r.margin;
}

// One projection, after the body's coupling: a hard inequality, the body moved out by the whole
// gap, then the slip relative to the surface since the substep began (the body's motion, its path
// and the surface's) removed up to Coulomb's bound. body_start: the offset at the substep's start.
inline void project_body_stop(BodyStopRow& r, ProxyBody& body, const Vec3& body_start, Real tau0,
                              Real tau1) {
  if (!body.active()) return;
  const Real gap = body_stop_gap(r, body, tau1);
  if (!(gap < 0)) return;
  const Real dn = -gap;
  body.offset += dn * r.normal;
  body.impulse += (body.damping * dn) * r.normal;
  r.depth = dn > r.depth ? dn : r.depth;
  r.normal_impulse += body.damping * dn;
  const Real span = tau1 - tau0;
  const Vec3 slip =
      span * (r.point1 - r.point0) + (body.offset - body_start) - span * (r.surface1 - r.surface0);
  const Vec3 slip_t = slip - slip.dot(r.normal) * r.normal;
  const Vec3 removed = friction_correction(r, dn, slip_t);
  body.offset -= removed;
  body.impulse -= body.damping * removed;
  r.friction_impulse -= body.damping * removed;
}

}  // namespace imasim::physics
