// The tool proxy (virtual coupling, surgery/tool_proxy.hpp): a device pressed into a membrane
// leaves the proxy on the tissue's surface where the tissue's reaction balances the coupling
// spring, so eq. 17's force k_d d (d the device's depth past the proxy) is the force the tissue
// pushes back with; releasing returns it to zero; the force stays bounded however deep the hand.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "haptics/force_law.hpp"
#include "haptics/force_params.hpp"
#include "physics/executor.hpp"
#include "surgery/tool_contact.hpp"
#include "surgery/tool_proxy.hpp"
#include "tissue/mesh_object.hpp"
#include "tissue/thoracic_patch.hpp"
#include "tissue/tissue_step.hpp"

namespace imasim::surgery {
namespace {

constexpr std::uint32_t kTag = 7;
constexpr Real kProbeRadius = Real(0.005);  // a ball-ended probe (unit: m)

// A fascia with its perimeter fixed, without gravity, flat in the x-z plane (normal +y), and a
// ball probe coupled to a device pose by the proxy.
struct PressRig {
  tissue::TissueWorld world;
  std::uint32_t mesh = 0;
  std::vector<Tissue> object_tissue;
  Vec3 centre = Vec3::Zero();  // of the membrane, on its surface
  ProxyParams params;
  ProxyState proxy;
  Vec3 previous_probe = Vec3::Zero();
  physics::Executor exec{1};

  PressRig() {
    world.model.solver = tissue::default_solver();
    tissue::FasciaParams f = tissue::default_fascia_params();
    f.object.gravity = false;
    mesh = tissue::add_fascia(world, f);
    tissue::finish_setup(world);
    object_tissue.assign(world.model.objects.size(), Tissue::none);
    object_tissue[world.meshes[mesh].object] = Tissue::fascia;
    const auto x = tissue::mesh_positions(world, world.meshes[mesh]);
    Vec3 lo = x[0], hi = x[0];
    for (const Vec3& p : x)
      lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    centre = Real(0.5) * (lo + hi);
  }

  Vec3 probe(const Vec3& device) const { return device + proxy.offset; }

  // The device lowered from 10 mm above the membrane to `device` at 20 mm/s, then held there
  // until `steps` steps have passed.
  void press(const Vec3& device, int steps) {
    const Vec3 start = device + Vec3(0, Real(0.01) + Real(0.005), 0);
    previous_probe = start;
    for (int k = 0; k < steps; ++k) {
      const Real travel = std::min(Real(1), Real(k) * Real(0.005) * Real(0.02) / Real(0.015));
      step(start + travel * (device - start));
    }
  }

  // One 5 ms step with the device's ball centre at `device`.
  void step(const Vec3& device) {
    const Real dt = world.model.solver.dt;
    const Vec3 at = probe(device);
    ToolGeometry tool;
    tool.capsules.push_back({at, at, kProbeRadius});
    tool.velocity = (at - previous_probe) / dt;
    Pose before, now;
    before.translation = previous_probe;
    now.translation = at;
    world.state.contacts.clear();
    gather_tool_contacts(world.state.particles, tool, before, now, ContactParams{}, dt, kTag,
                         world.state.contacts);
    ASSERT_TRUE(tissue::step_tissue(world, exec).ok());
    Tissue pressed = Tissue::none;
    const Vec3 force =
        tissue_force_on_tool(world.state.contacts, world.state.particles.object.data(),
                             object_tissue.data(), object_tissue.size(), kTag, dt, pressed);
    update_proxy(params, force, pressed, proxy);
    previous_probe = at;
  }

  // Closest distance from the probe's centre to the membrane's particles.
  Real clearance(const Vec3& device) const {
    Real best = 1;
    for (const Vec3& p : tissue::mesh_positions(world, world.meshes[mesh]))
      best = std::min(best, (p - probe(device)).norm());
    return best;
  }
};

TEST(ToolProxy, PressingFiveMillimetresRestsOnTheSurfaceWithEquationSeventeensForce) {
  PressRig rig;
  // The ball's lowest point 5 mm past the membrane's rest surface, pressed along -y.
  const Vec3 device = rig.centre + Vec3(0, kProbeRadius - Real(0.005), 0);
  rig.press(device, 600);
  const ProxyState& p = rig.proxy;
  EXPECT_EQ(p.pressed, Tissue::fascia);
  // The tissue pushes the tool back along +y and stopped the proxy short of the device (the
  // fascia's toe region is soft: about 10 mN at 5 mm, so the proxy is 0.03 mm short).
  EXPECT_GT(p.tissue_force.y(), 0.005);
  EXPECT_GT(p.offset.y(), 1e-5);
  EXPECT_LT(p.offset.y(), 0.005);
  // The proxy rests on the surface: the membrane touches the ball (radius + the contact margin).
  EXPECT_NEAR(rig.clearance(device), kProbeRadius + ContactParams{}.margin, 0.0003);
  // Eq. 17 with d = the device's depth past the proxy along the normal, at rest (v_n = 0), is
  // the force the tissue pushes back with (the proxy is at its balance).
  const haptics::ContactForceParams fascia =
      haptics::default_force_model_params().of(haptics::TissueKind::fascia);
  haptics::ContactKinematics contact;
  contact.normal = Vec3::UnitY();
  contact.depth = p.offset.dot(contact.normal);
  const haptics::ForceChannels f = haptics::contact_force(fascia, nullptr, 0, contact);
  EXPECT_NEAR(f.normal_n, fascia.stiffness * contact.depth, 1e-12);
  EXPECT_NEAR(f.normal_n, p.tissue_force.norm(), 0.03 * p.tissue_force.norm());
  EXPECT_NEAR(p.tissue_force.x(), 0, 0.02 * p.tissue_force.norm());
  EXPECT_NEAR(p.tissue_force.z(), 0, 0.02 * p.tissue_force.norm());

  // Released: the device lifted 10 mm clear; the force and the offset return to zero.
  const Vec3 lifted = rig.centre + Vec3(0, Real(0.01) + kProbeRadius, 0);
  for (int k = 0; k < 100; ++k)
    rig.step(lifted);
  EXPECT_EQ(rig.proxy.pressed, Tissue::none);
  EXPECT_EQ(rig.proxy.tissue_force, Vec3::Zero());
  EXPECT_LT(rig.proxy.offset.norm(), 1e-9);
}

TEST(ToolProxy, StiffnessOfTheCouplingSetsTheIndentation) {
  // A stiffer coupling lets the tissue stop the proxy less: it indents the membrane deeper and
  // the force k d is larger (a weak spring gives way instead). Pressed 12 mm, where the membrane's
  // reaction (growing as the cube of the indentation) is a few tenths of a newton.
  Real force[2], depth[2];
  for (int s = 0; s < 2; ++s) {
    PressRig rig;
    rig.params.stiffness[std::size_t(Tissue::fascia)] = s == 0 ? 100 : 400;
    const Vec3 device = rig.centre + Vec3(0, kProbeRadius - Real(0.012), 0);
    rig.press(device, 800);
    force[s] = rig.proxy.tissue_force.norm();
    depth[s] = Real(0.012) - rig.proxy.offset.y();
    EXPECT_NEAR(force[s], rig.params.stiffness[1] * rig.proxy.offset.y(), 0.03 * force[s]);
  }
  EXPECT_GT(force[1], 1.2 * force[0]);
  EXPECT_GT(depth[1], depth[0] + 0.0002);
}

TEST(ToolProxy, BalanceRelaxationAndBound) {
  ProxyParams params;
  ProxyState state;
  const Real k = params.stiffness[std::size_t(Tissue::ima)];
  // A steady 1 N along +z: the offset approaches 1 N / k, halving the gap each step.
  for (int n = 1; n <= 40; ++n) {
    update_proxy(params, Vec3(0, 0, 1), Tissue::ima, state);
    EXPECT_NEAR(state.offset.z(), (1 - std::pow(0.5, n)) / k, 1e-12) << n;
  }
  // However hard the tissue pushes, the proxy stays within max_offset of the device.
  for (int n = 0; n < 40; ++n)
    update_proxy(params, Vec3(1e6, 0, 0), Tissue::ima, state);
  EXPECT_NEAR(state.offset.norm(), params.max_offset, 1e-12);
  // A non-finite force is no force.
  update_proxy(params, Vec3(NAN, 0, 0), Tissue::ima, state);
  EXPECT_EQ(state.tissue_force, Vec3::Zero());
  EXPECT_TRUE(state.offset.allFinite());
}

TEST(ToolProxy, AgainstTissueFarStifferThanTheCouplingTheProxySettlesInsteadOfSwinging) {
  // Tissue of local stiffness k_t = 20 k pushing with F = F0 - k_t o (o the offset along z): the
  // balance is o* = F0 / (k + k_t). A fixed relaxation of 0.5 multiplies the error by
  // 1 - 0.5 (1 + 20) = -9.5 a step and swings the proxy from bound to bound; the secant estimate
  // of k_t brings the step down to k / (k + k_t) and the proxy settles on o*.
  ProxyParams params;
  ProxyState state;
  const Real k = params.stiffness[std::size_t(Tissue::ima)], k_t = 20 * k, f0 = 1;
  const Real balance = f0 / (k + k_t);
  Real largest = 0;
  for (int n = 0; n < 60; ++n) {
    update_proxy(params, Vec3(0, 0, f0 - k_t * state.offset.z()), Tissue::ima, state);
    largest = std::max(largest, state.offset.norm());
  }
  EXPECT_NEAR(state.offset.z(), balance, 1e-6 * balance);
  EXPECT_LT(largest, params.max_offset);  // never thrown to the bound
  // With the fixed relaxation (no memory of k_t: the estimate forgotten each step) it swings.
  ProxyState fixed;
  ProxyParams forgetful = params;
  forgetful.stiffness_memory = 0;
  Real swing = 0;
  for (int n = 0; n < 60; ++n) {
    fixed.last_change = Vec3::Zero();  // no secant: the relaxation stays at 0.5
    update_proxy(forgetful, Vec3(0, 0, f0 - k_t * fixed.offset.z()), Tissue::ima, fixed);
    swing = std::max(swing, fixed.offset.norm());
  }
  EXPECT_NEAR(swing, params.max_offset, 1e-12);
}

TEST(ToolProxy, ForceOnTheToolIsTheOppositeOfTheContactsImpulsesPerStep) {
  physics::ContactSet contacts;
  physics::ContactRow a, b, other;
  a.particle = 0, a.tag = kTag, a.normal = Vec3::UnitY(), a.normal_impulse = 0.002;
  b.particle = 1, b.tag = kTag, b.normal = Vec3::UnitX(), b.normal_impulse = 0.001;
  other.particle = 2, other.tag = kTag + 1, other.normal = Vec3::UnitZ(), other.normal_impulse = 5;
  contacts.rows = {a, b, other};
  const physics::ObjectId object[3] = {0, 1, 1};
  const Tissue tissue[2] = {Tissue::ima, Tissue::fat};
  Tissue pressed = Tissue::none;
  const Vec3 f = tissue_force_on_tool(contacts, object, tissue, 2, kTag, 0.005, pressed);
  EXPECT_NEAR((f - Vec3(-0.2, -0.4, 0)).norm(), 0, 1e-12);
  EXPECT_EQ(pressed, Tissue::ima);  // the larger impulse
}

TEST(ToolProxy, CouplingStiffnessDefaultsAreTheForceLawsStiffness) {
  const ProxyParams params;
  const haptics::ForceModelParams law = haptics::default_force_model_params();
  const std::pair<Tissue, haptics::TissueKind> pairs[] = {
      {Tissue::fascia, haptics::TissueKind::fascia},
      {Tissue::ima, haptics::TissueKind::ima},
      {Tissue::fat, haptics::TissueKind::fat},
      {Tissue::heart, haptics::TissueKind::heart},
      {Tissue::chest_wall, haptics::TissueKind::chest_wall}};
  for (const auto& [tissue, kind] : pairs)
    EXPECT_EQ(params.stiffness[std::size_t(tissue)], law.of(kind).stiffness);
}

}  // namespace
}  // namespace imasim::surgery
