#pragma once
// An instrument's proxy as a body inside the solve (virtual coupling, SPEC S5 reading).
// The instrument follows a kinematic path, the device pose the hand asks for, moved by an offset
// o: the body's one unknown. A contact row that names the body (ContactRow::body) is a two-body
// constraint: its particle and the proxy share each correction by their inverse masses, so
// tissue that resists the tool pushes the tool back within the same substep. Eq. 17's spring
// and damper hold the proxy to the device:
//   k (o - o_rest) + c do/dt = F_contacts     (k = k_d, c = c_d of the tissue pressed)
// The proxy has no inertia of its own: over a substep of length h the damper resists a
// displacement delta with the impulse c delta, so the body weighs c h (`proxy_inverse_mass`), and
// the spring is an XPBD constraint o = o_rest of compliance 1 / k. One projection of it is the
// implicit Euler step of c do/dt = -k (o - o_rest): o - o_rest shrinks by c / (c + k h). At rest
// k (o - o_rest) is the force the tissue pushes the tool with: eq. 17's k_d d, d the device's
// depth past the proxy. o_rest carries what the solve does not see (the pull of held tissue, one
// step behind); |o| never exceeds max_offset, so the force stays bounded however far the hand goes.
#include <cstdint>
#include <limits>
#include <vector>

#include "math/types.hpp"

namespace imasim::physics {

inline constexpr std::uint32_t kNoBody = std::numeric_limits<std::uint32_t>::max();

struct ProxyBody {
  // Set by the owner before each step.
  Real stiffness = 0;        // k, the coupling's spring (unit: N/m); <= 0: no proxy (kinematic)
  Real damping = 0;          // c, the coupling's damper (unit: N s/m); <= 0: no proxy
  Vec3 rest = Vec3::Zero();  // o_rest, where the spring is relaxed (unit: m)
  Real max_offset = Real(0.015);  // bound on |o| (unit: m)
  // The unknown, carried from step to step: the proxy's offset from the device path (unit: m).
  Vec3 offset = Vec3::Zero();
  // Kept by the step: the offset at the step's start, at the fine substep's and at the coarse
  // substep's (ObjectParams::coarse) (unit: m).
  Vec3 step_start = Vec3::Zero(), substep_start = Vec3::Zero(), coarse_start = Vec3::Zero();
  Vec3 lambda = Vec3::Zero();  // the spring's multiplier in this substep (unit: N s^2)
  // The impulse the contacts put on the tool over the step, normal and friction (unit: N s): a
  // correction delta of the body is the impulse c delta (its mass c h over the substep h).
  Vec3 impulse = Vec3::Zero();

  bool active() const { return stiffness > 0 && damping > 0; }
  // How far the tool has moved off its gathered path so far in this step (unit: m): the rows
  // were gathered with the tool where the step began.
  Vec3 carried() const { return offset - step_start; }
};

// The body's inverse mass over a substep of length h: 1 / (c h) (unit: 1/kg); 0 when inactive.
inline Real proxy_inverse_mass(const ProxyBody& b, Real h) {
  return b.active() ? 1 / (b.damping * h) : Real(0);
}

// The coupling, after each iteration's contacts: the XPBD spring o = o_rest (compliance 1 / k,
// alpha~ = 1 / (k h^2)) against the body's mass c h: dlambda = (-(o - o_rest) - alpha~ lambda) /
// (w + alpha~), o += w dlambda. The first projection of a substep multiplies o - o_rest by
// c / (c + k h). Then the bound.
inline void project_proxy_coupling(ProxyBody& b, Real h) {
  if (!b.active()) return;
  const Real w = proxy_inverse_mass(b, h);
  const Real alpha = 1 / (b.stiffness * h * h);
  const Vec3 dlambda = (b.rest - b.offset - alpha * b.lambda) / (w + alpha);
  b.offset += w * dlambda;
  b.lambda += dlambda;
  const Real length = b.offset.norm();
  if (length > b.max_offset) b.offset *= b.max_offset / length;
}

// A body that is not finite (a diverged step, a caller's NaN) is put back where the step began,
// or at the device if that is not finite either.
inline void keep_proxy_finite(ProxyBody& b) {
  if (b.offset.allFinite()) return;
  b.offset = b.step_start.allFinite() ? b.step_start : Vec3::Zero();
}

}  // namespace imasim::physics
