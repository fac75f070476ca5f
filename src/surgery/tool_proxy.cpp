#include "surgery/tool_proxy.hpp"

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
  state.tissue_force = tissue_force.allFinite() ? tissue_force : Vec3::Zero();
  state.pressed = pressed;
  const Real k = params.stiffness[std::size_t(pressed)];
  const Vec3 balance =
      pressed == Tissue::none || !(k > 0) ? Vec3::Zero() : Vec3(state.tissue_force / k);
  state.offset += params.relaxation * (balance - state.offset);
  const Real length = state.offset.norm();
  if (length > params.max_offset) state.offset *= params.max_offset / length;
}

}  // namespace imasim::surgery
