#pragma once
// A particle held by a proxy body (the forceps' grasp): the attachment of
// attachment_constraint.hpp, C = p - t, with the target t riding on the body, carried by the
// offset the body moves by within the step. Particle and body share each correction by their
// inverse masses (the body weighs c h over a substep h, proxy_body.hpp), so held tissue pulls the
// tool back within the same substeps in which the tool pulls it, and its pull is part of the
// impulse the body receives (c times each of its corrections), as a contact's push is. Projected
// serially: the rows share their body.
#include <cstdint>
#include <span>

#include "math/types.hpp"
#include "physics/proxy_body.hpp"

namespace imasim::physics {

struct BodyAttachmentRow {
  std::uint32_t particle = 0;
  std::uint32_t body = 0;      // the proxy body (State::proxies)
  Vec3 target = Vec3::Zero();  // on the tool's gathered path, before the body's carry (unit: m)
  Real compliance = 0;         // alpha (unit: m/N)
  Vec3 lambda = Vec3::Zero();  // this substep's multipliers, one per axis (unit: N s^2)
  // The impulse the hold put on the body over the step (unit: N s; / dt gives the mean pull).
  Vec3 impulse = Vec3::Zero();
  // A kinematic particle is left alone, unless this is set: then it holds the body, which takes
  // the whole correction (the implicit fascia, solved before the XPBD step and held still in it).
  bool holds_body = false;
};

// XPBD on the three linear rows at once, in a substep of length h: alpha~ = alpha / h^2,
// d_lambda = (-C - alpha~ lambda) / (w_p + w_b + alpha~); the particle moves by w_p d_lambda, the
// body by -w_b d_lambda (the target moves with it). A fixed particle is left alone, or holds the
// body (holds_body).
inline void project_body_attachment(BodyAttachmentRow& r, Vec3* p, const Real* w, ProxyBody& body,
                                    Real h) {
  const Real wp = w[r.particle];
  const Real wb = proxy_inverse_mass(body, h);
  if (wp == 0 && !(r.holds_body && wb > 0)) return;
  const Real alpha = r.compliance / (h * h);
  const Vec3 c = p[r.particle] - (r.target + body.carried());
  const Vec3 dl = (-c - alpha * r.lambda) / (wp + wb + alpha);
  r.lambda += dl;
  p[r.particle] += wp * dl;
  const Vec3 moved = -wb * dl;
  body.offset += moved;
  body.impulse += body.damping * moved;
  r.impulse += body.damping * moved;
}

// The mean pull of the holds of `body` on it over the last step of length dt (unit: N).
inline Vec3 held_pull_on_body(std::span<const BodyAttachmentRow> rows, std::uint32_t body,
                              Real dt) {
  Vec3 impulse = Vec3::Zero();
  for (const BodyAttachmentRow& r : rows)
    if (r.body == body) impulse += r.impulse;
  return dt > 0 ? Vec3(impulse / dt) : Vec3::Zero();
}

}  // namespace imasim::physics
