// The tool proxy (virtual coupling, surgery/tool_proxy.hpp): a device pressed into a membrane
// leaves the proxy, a body inside the solve, on the tissue's surface where the tissue's reaction
// balances the coupling spring, so eq. 17's force k_d d (d the device's depth past the proxy) is
// the force the tissue pushes back with; releasing returns it to zero; the held tissue's pull
// moves the spring's rest without swinging; the force stays bounded however deep the hand.
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
  Vec3 normal_force = Vec3::Zero();  // the contacts' normal impulses alone, over the last step
  physics::Executor exec{1};

  PressRig() {
    world.state.proxies.assign(1, physics::ProxyBody{});
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
    prepare_proxy_body(params, proxy, world.state.contacts.rows, 0,
                       world.state.particles.object.data(), object_tissue.data(),
                       object_tissue.size(), world.state.proxies[0]);
    ASSERT_TRUE(tissue::step_tissue(world, exec).ok());
    Tissue pressed = Tissue::none;
    normal_force =
        tissue_force_on_tool(world.state.contacts, world.state.particles.object.data(),
                             object_tissue.data(), object_tissue.size(), kTag, dt, pressed);
    finish_proxy_step(world.state.proxies[0], dt, normal_force, pressed, Vec3::Zero(), Tissue::none,
                      Tissue::none, proxy);
    previous_probe = at + world.state.proxies[0].carried();  // where the solve left the tool
  }

  // Closest distance from the probe's centre to the membrane's particles.
  Real clearance(const Vec3& device) const {
    Real best = 1;
    for (const Vec3& p : tissue::mesh_positions(world, world.meshes[mesh]))
      best = std::min(best, (p - probe(device)).norm());
    return best;
  }
};

TEST(ToolProxy, PressingFiveMillimetresRestsOnTheSurfaceAndTheCouplingCarriesTheTissuesPush) {
  PressRig rig;
  // The ball's lowest point 5 mm past the membrane's rest surface, pressed along -y.
  const Vec3 device = rig.centre + Vec3(0, kProbeRadius - Real(0.005), 0);
  rig.press(device, 600);
  const ProxyState& p = rig.proxy;
  EXPECT_EQ(p.pressed, Tissue::fascia);
  // The tissue pushes the tool back along +y and stopped the proxy short of the device (the
  // fascia's toe region is soft: about 10 mN at 5 mm, so the stiff coupling leaves the proxy
  // 0.01 mm short).
  EXPECT_GT(p.tissue_force.y(), 0.005);
  EXPECT_GT(p.offset.y(), 2e-6);
  EXPECT_LT(p.offset.y(), 0.005);
  // The proxy rests on the surface: the membrane touches the ball (radius + the contact margin).
  EXPECT_NEAR(rig.clearance(device), kProbeRadius + ContactParams{}.margin, 0.0003);
  // At its balance the coupling carries all the tissue puts on the tool: k o = F, what the local
  // model renders (console/local_model_of.hpp).
  const Real force = p.tissue_force.norm();
  EXPECT_LT((p.tissue_force - rig.params.coupling_stiffness * p.offset).norm(), 0.03 * force);
  // The contacts' normal push is along +y; the membrane wrapped on the ball holds some friction
  // (static, locked in as it was pressed), inside the Coulomb cone mu_s of the normal push.
  const Real normal = rig.normal_force.norm();
  EXPECT_NEAR(rig.normal_force.x(), 0, 0.02 * normal);
  EXPECT_NEAR(rig.normal_force.z(), 0, 0.02 * normal);
  EXPECT_LE((p.tissue_force - rig.normal_force).norm(), ContactParams{}.static_friction * normal);

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
    rig.params.coupling_stiffness = s == 0 ? 100 : 400;
    const Vec3 device = rig.centre + Vec3(0, kProbeRadius - Real(0.012), 0);
    rig.press(device, 800);
    force[s] = rig.proxy.tissue_force.norm();
    depth[s] = Real(0.012) - rig.proxy.offset.y();
    const Real k = rig.params.coupling_stiffness;
    EXPECT_LT((rig.proxy.tissue_force - k * rig.proxy.offset).norm(), 0.03 * force[s]);
  }
  EXPECT_GT(force[1], 1.2 * force[0]);
  EXPECT_GT(depth[1], depth[0] + 0.0002);
}

TEST(ToolProxy, AfterAStepTheToolFeelsEverythingItsBodyReceived) {
  // The body received 0.1 N of push, 0.02 N of friction and the held tissue's 0.3 N pull over
  // the 5 ms step (the pull is inside the solve). The normal channel is the contacts' normal push
  // and the pull, without the contacts' friction; the pressed tissue is the larger part's.
  physics::ProxyBody body;
  body.offset = Vec3(0, 0.001, 0);
  body.impulse = 0.005 * Vec3(0.02, 0.1, -0.3);
  ProxyState after;
  finish_proxy_step(body, 0.005, Vec3(0, 0.1, 0), Tissue::fascia, Vec3(0, 0, -0.3), Tissue::ima,
                    Tissue::heart, after);
  EXPECT_EQ(after.stopped_by, Tissue::heart);
  EXPECT_EQ(after.offset, body.offset);
  EXPECT_NEAR((after.tissue_force - Vec3(0.02, 0.1, -0.3)).norm(), 0, 1e-15);
  EXPECT_NEAR((after.normal_force - Vec3(0, 0.1, -0.3)).norm(), 0, 1e-15);
  EXPECT_EQ(after.pull, Vec3(0, 0, -0.3));
  EXPECT_EQ(after.pressed, Tissue::ima);
  EXPECT_EQ(after.held, Tissue::ima);
  // Held against the heart, which pushes harder than the tissue pulls: the normal channel is
  // still the held tissue's (the heart is rendered as its own contact), and the coupling's k is
  // kept for the local model.
  body.stiffness = 200;
  body.impulse = 0.005 * Vec3(0, 0.5, -0.3);
  finish_proxy_step(body, 0.005, Vec3::Zero(), Tissue::none, Vec3(0, 0, -0.3), Tissue::ima,
                    Tissue::heart, after);
  EXPECT_EQ(after.pressed, Tissue::ima);
  EXPECT_EQ(after.held, Tissue::ima);
  EXPECT_EQ(after.coupling, 200);
  // A non-finite push or pull is none.
  finish_proxy_step(body, 0.005, Vec3(NAN, 0, 0), Tissue::fascia, Vec3(0, INFINITY, 0), Tissue::ima,
                    Tissue::none, after);
  EXPECT_EQ(after.normal_force, Vec3::Zero());
  EXPECT_EQ(after.pull, Vec3::Zero());
  EXPECT_EQ(after.pressed, Tissue::fascia);
  EXPECT_EQ(after.held, Tissue::none);
}

// The coupling is one for every tissue: whichever tissue the rows touch, the jaws hold or
// stopped the proxy in the last step. A coupling that followed them switched between steps as
// rows came and went (the held hook's force chattered between the fascia's and the fat's k).
TEST(ToolProxy, TheCouplingIsOneWhateverTheToolTouches) {
  ProxyParams params;
  params.coupling_stiffness = 1500;
  params.coupling_damping = 6;
  const physics::ObjectId particle_object[2] = {0, 1};
  const Tissue object_tissue[2] = {Tissue::fascia, Tissue::fat};
  std::vector<physics::ContactRow> rows(3);
  rows[0].particle = 0;
  rows[1].particle = rows[2].particle = 1;  // mostly fat
  ProxyState state;
  state.held = Tissue::ima;
  state.stopped_by = Tissue::heart;
  state.pressed = Tissue::fascia;
  for (std::size_t n : {std::size_t(0), std::size_t(1), std::size_t(3)}) {
    physics::ProxyBody body;
    prepare_proxy_body(params, state, std::span(rows).first(n), 0, particle_object, object_tissue,
                       2, body);
    EXPECT_EQ(body.stiffness, 1500) << n;
    EXPECT_EQ(body.damping, 6) << n;
    state.held = Tissue::none;
  }
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

TEST(ToolProxy, CouplingDefaultsAreTheForceLawsSpringAndDamper) {
  const ProxyParams params;
  const haptics::ForceModelParams law = haptics::default_force_model_params();
  const std::pair<Tissue, haptics::TissueKind> pairs[] = {
      {Tissue::fascia, haptics::TissueKind::fascia},
      {Tissue::ima, haptics::TissueKind::ima},
      {Tissue::fat, haptics::TissueKind::fat},
      {Tissue::heart, haptics::TissueKind::heart},
      {Tissue::chest_wall, haptics::TissueKind::chest_wall}};
  for (const auto& [tissue, kind] : pairs) {
    EXPECT_EQ(params.stiffness[std::size_t(tissue)], law.of(kind).stiffness);
    EXPECT_EQ(params.friction[std::size_t(tissue)], law.of(kind).friction);
  }
}

// Each contact row takes the friction of the tissue its particle belongs to (eq. 18's mu, static
// and kinetic alike); a particle of no tissue keeps what the gathering gave it.
TEST(ToolProxy, EachRowTakesItsTissuesFriction) {
  ProxyParams params;
  params.friction[std::size_t(Tissue::fascia)] = Real(0.25);
  params.friction[std::size_t(Tissue::fat)] = Real(0.05);
  const physics::ObjectId particle_object[3] = {0, 1, 2};
  const Tissue object_tissue[3] = {Tissue::fascia, Tissue::fat, Tissue::none};
  std::vector<physics::ContactRow> rows(3);
  for (std::uint32_t i = 0; i < 3; ++i) {
    rows[i].particle = i;
    rows[i].static_friction = Real(0.6);
    rows[i].kinetic_friction = Real(0.4);
  }
  physics::ProxyBody body;
  prepare_proxy_body(params, ProxyState{}, rows, 0, particle_object, object_tissue, 3, body);
  EXPECT_EQ(rows[0].static_friction, Real(0.25));
  EXPECT_EQ(rows[0].kinetic_friction, Real(0.25));
  EXPECT_EQ(rows[1].static_friction, Real(0.05));
  EXPECT_EQ(rows[1].kinetic_friction, Real(0.05));
  EXPECT_EQ(rows[2].static_friction, Real(0.6));
  EXPECT_EQ(rows[2].kinetic_friction, Real(0.4));
  EXPECT_EQ(rows[0].body, 0u);
}

}  // namespace
}  // namespace imasim::surgery
