#include "surgery/tool_proxy.hpp"

#include <algorithm>
#include <cmath>

namespace imasim::surgery {
namespace {

Tissue tissue_of(const physics::ObjectId* particle_object, const Tissue* object_tissue,
                 std::size_t object_count, std::uint32_t particle) {
  const std::size_t object = particle_object[particle];
  return object < object_count ? object_tissue[object] : Tissue::none;
}

// The tissue with the largest share (none when every share is zero).
Tissue largest(const std::array<Real, kTissueCount>& share) {
  Tissue best = Tissue::none;
  Real most = 0;
  for (int t = 1; t < kTissueCount; ++t) {
    if (share[std::size_t(t)] > most) {
      most = share[std::size_t(t)];
      best = Tissue(t);
    }
  }
  return best;
}

}  // namespace

Vec3 tissue_force_on_tool(const physics::ContactSet& contacts,
                          const physics::ObjectId* particle_object, const Tissue* object_tissue,
                          std::size_t object_count, std::uint32_t tag, Real dt, Tissue& pressed) {
  Vec3 impulse = Vec3::Zero();
  std::array<Real, kTissueCount> share{};
  for (const physics::ContactRow& c : contacts.rows) {
    if (c.tag != tag || !(c.normal_impulse > 0)) continue;
    impulse -= c.normal_impulse * c.normal;  // the particle got +J n, the tool -J n
    share[std::size_t(tissue_of(particle_object, object_tissue, object_count, c.particle))] +=
        c.normal_impulse;
  }
  pressed = largest(share);
  return dt > 0 ? Vec3(impulse / dt) : Vec3::Zero();
}

void prepare_proxy_body(const ProxyParams& params, const ProxyState& state,
                        std::span<physics::ContactRow> rows, std::uint32_t body_index,
                        const physics::ObjectId* particle_object, const Tissue* object_tissue,
                        std::size_t object_count, physics::ProxyBody& body) {
  for (physics::ContactRow& c : rows) {
    c.body = body_index;
    const Tissue touched = tissue_of(particle_object, object_tissue, object_count, c.particle);
    if (touched == Tissue::none) continue;
    c.static_friction = c.kinetic_friction = params.friction[std::size_t(touched)];
  }
  body.stiffness = params.coupling_stiffness;
  body.damping = params.coupling_damping;
  body.max_offset = params.max_offset;
  body.rest = Vec3::Zero();
  body.offset = state.offset;
}

void finish_proxy_step(const physics::ProxyBody& body, Real dt, const Vec3& normal_push,
                       Tissue pressed, const Vec3& pull, Tissue pull_tissue, Tissue stopped_by,
                       ProxyState& state) {
  state.stopped_by = stopped_by;
  state.coupling = body.stiffness;
  state.offset = body.offset.allFinite() ? body.offset : Vec3::Zero();
  state.tissue_force = dt > 0 && body.impulse.allFinite() ? Vec3(body.impulse / dt) : Vec3::Zero();
  state.pull = pull.allFinite() ? pull : Vec3::Zero();
  const Vec3 push = normal_push.allFinite() ? normal_push : Vec3::Zero();
  state.normal_force = push + state.pull;
  // The heart's or the wall's push is rendered apart (console/local_model_of.cpp): it does not
  // decide which tissue the normal channel is.
  state.held = state.pull.squaredNorm() > 0 ? pull_tissue : Tissue::none;
  state.pressed = state.pull.squaredNorm() > push.squaredNorm() ? pull_tissue : pressed;
}

}  // namespace imasim::surgery
