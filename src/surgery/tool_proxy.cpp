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
                        std::span<physics::ContactRow> rows,
                        std::span<const physics::BodyStopRow> stops, std::uint32_t body_index,
                        const physics::ObjectId* particle_object, const Tissue* object_tissue,
                        std::size_t object_count, physics::ProxyBody& body) {
  std::array<Real, kTissueCount> count{};
  for (physics::ContactRow& c : rows) {
    c.body = body_index;
    const Tissue touched = tissue_of(particle_object, object_tissue, object_count, c.particle);
    count[std::size_t(touched)] += 1;
    if (touched == Tissue::none) continue;
    c.static_friction = c.kinetic_friction = params.friction[std::size_t(touched)];
  }
  for (const physics::BodyStopRow& r : stops) {
    if (r.tag < std::uint32_t(kTissueCount)) count[r.tag] += 1;
  }
  Tissue tissue = largest(count);
  if (tissue == Tissue::none) tissue = state.pressed;
  if (tissue == Tissue::none) tissue = Tissue::fascia;
  body.stiffness = params.stiffness[std::size_t(tissue)];
  body.damping = params.damping[std::size_t(tissue)];
  body.max_offset = params.max_offset;
  body.rest = state.rest;
  body.offset = state.offset;
}

void relax_held_pull(const ProxyParams& params, const Vec3& pull, Tissue pull_tissue,
                     ProxyState& state) {
  const Vec3 force = pull.allFinite() ? pull : Vec3::Zero();
  // Secant estimate of the held tissue's stiffness along o_rest's last change:
  // k_t = -dF.do/|do|^2 (unit: N/m), only from changes large enough to measure.
  constexpr Real kMeasurable = Real(1e-7);  // (unit: m)
  // It decays only as new measurements come: at rest (no measurable change) it holds.
  Real k_t = state.pull_stiffness;
  const Real moved = state.last_change.squaredNorm();
  if (moved > kMeasurable * kMeasurable) {
    const Real secant = -(force - state.pull).dot(state.last_change) / moved;
    if (std::isfinite(secant)) k_t = std::max(params.stiffness_memory * k_t, secant);
  }
  state.pull_stiffness = k_t;
  state.pull = force;
  const Real k = params.stiffness[std::size_t(pull_tissue)];
  const Vec3 balance = pull_tissue == Tissue::none || !(k > 0) ? Vec3::Zero() : Vec3(force / k);
  const Real r = k > 0 ? std::min(params.relaxation, k / (k + k_t)) : params.relaxation;
  const Vec3 before = state.rest;
  state.rest += r * (balance - state.rest);
  const Real length = state.rest.norm();
  if (length > params.max_offset) state.rest *= params.max_offset / length;
  state.last_change = state.rest - before;
}

void finish_proxy_step(const ProxyParams& params, const physics::ProxyBody& body, Real dt,
                       const Vec3& normal_push, Tissue pressed, const Vec3& pull,
                       Tissue pull_tissue, ProxyState& state) {
  state.offset = body.offset.allFinite() ? body.offset : Vec3::Zero();
  const Vec3 contact = dt > 0 && body.impulse.allFinite() ? Vec3(body.impulse / dt) : Vec3::Zero();
  const Vec3 held = pull.allFinite() ? pull : Vec3::Zero();
  state.tissue_force = contact + held;
  state.normal_force = (normal_push.allFinite() ? normal_push : Vec3::Zero()) + held;
  state.pressed = held.squaredNorm() > contact.squaredNorm() ? pull_tissue : pressed;
  relax_held_pull(params, held, pull_tissue, state);
}

}  // namespace imasim::surgery
