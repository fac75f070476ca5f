#include "surgery/tool_proxy.hpp"

#include <algorithm>
#include <cmath>

namespace imasim::surgery {

Vec3 tissue_force_on_tool(const physics::ContactSet& contacts,
                          const physics::ObjectId* particle_object, const Tissue* object_tissue,
                          std::size_t object_count, std::uint32_t tag, Real dt, Tissue& pressed) {
  Vec3 impulse = Vec3::Zero();
  std::array<Real, kTissueCount> share{};
  for (const physics::ContactRow& c : contacts.rows) {
    if (c.tag != tag || !(c.normal_impulse > 0)) continue;
    impulse -= c.normal_impulse * c.normal;  // the particle got +J n, the tool -J n
    const std::size_t object = particle_object[c.particle];
    const Tissue t = object < object_count ? object_tissue[object] : Tissue::none;
    share[std::size_t(t)] += c.normal_impulse;
  }
  pressed = Tissue::none;
  Real best = 0;
  for (int t = 1; t < kTissueCount; ++t) {
    if (share[std::size_t(t)] > best) {
      best = share[std::size_t(t)];
      pressed = Tissue(t);
    }
  }
  return dt > 0 ? Vec3(impulse / dt) : Vec3::Zero();
}

void update_proxy(const ProxyParams& params, const Vec3& tissue_force, Tissue pressed,
                  ProxyState& state) {
  const Vec3 force = tissue_force.allFinite() ? tissue_force : Vec3::Zero();
  // Secant estimate of the tissue's stiffness along the offset's last change: k_t = -dF.do/|do|^2
  // (unit: N/m), only from changes large enough to measure.
  constexpr Real kMeasurable = Real(1e-7);  // (unit: m)
  // It decays only as new measurements come: at rest (no measurable change) it holds.
  Real k_t = state.tissue_stiffness;
  const Real moved = state.last_change.squaredNorm();
  if (moved > kMeasurable * kMeasurable) {
    const Real secant = -(force - state.tissue_force).dot(state.last_change) / moved;
    if (std::isfinite(secant)) k_t = std::max(params.stiffness_memory * k_t, secant);
  }
  state.tissue_stiffness = k_t;
  state.tissue_force = force;
  state.pressed = pressed;
  const Real k = params.stiffness[std::size_t(pressed)];
  const Vec3 balance =
      pressed == Tissue::none || !(k > 0) ? Vec3::Zero() : Vec3(state.tissue_force / k);
  const Real r = k > 0 ? std::min(params.relaxation, k / (k + k_t)) : params.relaxation;
  const Vec3 before = state.offset;
  state.offset += r * (balance - state.offset);
  const Real length = state.offset.norm();
  if (length > params.max_offset) state.offset *= params.max_offset / length;
  state.last_change = state.offset - before;
}

}  // namespace imasim::surgery
