// A scripted surgical session: the example script opens the fascia beside the IMA, grasps and
// retracts the flap, cuts strands and coagulates, headless and deterministically (the vertices
// its cuts make follow the heart); instruments stop at the heart; heat on the IMA is recorded as
// injury.
#include "session/surgical_session.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "physics/executor.hpp"
#include "session/surface_stops.hpp"
#include "tissue/topology_change.hpp"

namespace imasim::session {
namespace {

const std::string kScript = std::string(IMASIM_SOURCE_DIR) + "/examples/open_fascia.script";

// after_step: called with the session after each step.
template <typename AfterStep>
SurgicalSession run_script(const surgery::InputScript& script, double seconds, int threads,
                           AfterStep after_step) {
  SurgicalSession s = make_surgical_session(scene::default_thorax_scene_params(), SessionParams{});
  physics::Executor exec(threads);
  tissue::TissueWorld& w = s.scene.patch.world;
  while (w.state.time < seconds) {
    const physics::StepResult r = step_session(s, sample_script(script, w.state.time), exec);
    EXPECT_TRUE(r.ok());
    if (!r.ok()) break;
    after_step(s);
  }
  return s;
}

SurgicalSession run_script(const surgery::InputScript& script, double seconds, int threads) {
  return run_script(script, seconds, threads, [](const SurgicalSession&) {});
}

// An input that commands the hook by its tool pose, where it is now.
SessionInput hook_held_where_it_is(const SurgicalSession& s) {
  SessionInput in;
  in.right.source = surgery::PoseSource::tool;
  in.right.pose = s.stations[1].pose;
  return in;
}

SurgicalSession session_with_a_still_heart() {
  scene::ThoraxSceneParams params = scene::default_thorax_scene_params();
  params.playback.beating = false;
  return make_surgical_session(params, SessionParams{});
}

TEST(SurgicalSession, TheExampleScriptOpensGraspsCutsAndCoagulates) {
  const surgery::InputScript script = surgery::load_input_script(kScript);
  SurgicalSession s = run_script(script, script.end_time() + 0.2, 1);
  const surgery::EventLog& log = s.events;
  using surgery::EventKind;
  EXPECT_GE(log.count(EventKind::fascia_cut), 20u);
  EXPECT_GE(s.fascia_edges_cut, 50u);
  EXPECT_GE(log.count(EventKind::strand_cut), 5u);
  EXPECT_EQ(log.count(EventKind::grasp), 1u);
  EXPECT_EQ(log.count(EventKind::release), 1u);
  EXPECT_EQ(log.count(EventKind::cautery_on), 3u);
  EXPECT_EQ(log.count(EventKind::cautery_off), 3u);
  EXPECT_EQ(log.count(EventKind::injury), 0u);  // the script keeps ~8 mm from the vessel
  std::size_t coagulated = 0;
  for (std::uint8_t c : s.cautery.coagulated)
    coagulated += c;
  EXPECT_GT(coagulated, 0u);
  // Events are in time order, and the grasp came before the release.
  for (std::size_t k = 1; k < log.events.size(); ++k)
    EXPECT_LE(log.events[k - 1].time, log.events[k].time);
  // The fascia is open and still sound.
  tissue::TissueWorld& w = s.scene.patch.world;
  geometry::MeshCheckOptions checks;
  checks.min_angle = s.params.fascia_cut.min_angle * (1 - 1e-12);
  checks.min_area = s.params.fascia_cut.min_area * (1 - 1e-12);
  EXPECT_EQ(tissue::first_topology_defect(w, s.scene.patch.fascia, checks), "");
  for (const Vec3& x : w.state.particles.position)
    ASSERT_TRUE(x.allFinite());
  // Every fascia vertex, those the cuts made too, follows the heart through one anchor.
  const tissue::MeshObject& fascia = w.meshes[s.scene.patch.fascia];
  ASSERT_GT(fascia.particle_count, 480u);
  std::vector<int> anchors(fascia.particle_count, 0);
  for (const tissue::HeartField::Anchor& a : s.scene.heart.anchors) {
    if (a.particle >= fascia.first_particle &&
        a.particle < fascia.first_particle + fascia.particle_count) {
      ++anchors[a.particle - fascia.first_particle];
    }
  }
  for (std::uint32_t k = 0; k < fascia.particle_count; ++k)
    EXPECT_EQ(anchors[k], 1) << "fascia vertex " << k;
  // The slivers the hook's cuts free are vaporised, not left to fall through the cavity (they
  // fell 0.27 m before; the sheet itself moves millimetres).
  EXPECT_GT(log.count(EventKind::fragment_vaporised), 5u);
  EXPECT_GT(s.fragments_vaporised, 5u);
  EXPECT_LT(tissue::max_displacement(w, fascia), 0.02);
}

// The script's forceps hold the flap's lip and retract it towards the heart (7.5-9.4 s), their
// jaws lying across its curve: the held tissue keeps the heart's margin, as its contacts keep it,
// because each held point stops the jaws (surface_stop_rows.hpp). Before, the holds, projected
// after the contacts, pulled 5 vertices 0.5 mm into the margin every step, and the check after the
// step put them out again: 1,228 times while they held.
TEST(SurgicalSession, TheTissueTheJawsHoldIsNotPulledIntoTheHeart) {
  const surgery::InputScript script = surgery::load_input_script(kScript);
  std::uint32_t held_steps = 0, missed_while_held = 0;
  run_script(script, 9.4, 1, [&](const SurgicalSession& s) {
    if (s.grasper.held.empty()) return;
    ++held_steps;
    missed_while_held += s.scene.missed_heart_contacts;
  });
  ASSERT_GT(held_steps, 500u);
  EXPECT_EQ(missed_while_held, 0u);
}

TEST(SurgicalSession, AScriptedSessionIsBitForBitRepeatableWhateverTheThreads) {
  const surgery::InputScript script = surgery::load_input_script(kScript);
  const SurgicalSession a = run_script(script, 2.0, 1);
  const SurgicalSession b = run_script(script, 2.0, 2);
  EXPECT_EQ(physics::position_hash(a.scene.patch.world.state),
            physics::position_hash(b.scene.patch.world.state));
  ASSERT_EQ(a.events.events.size(), b.events.events.size());
  for (std::size_t k = 0; k < a.events.events.size(); ++k) {
    EXPECT_EQ(a.events.events[k].time, b.events.events[k].time);
    EXPECT_EQ(a.events.events[k].kind, b.events.events[k].kind);
    EXPECT_EQ(a.events.events[k].count, b.events.events[k].count);
  }
}

TEST(SurgicalSession, InstrumentsStopAtTheHeart) {
  SurgicalSession s = make_surgical_session(scene::default_thorax_scene_params(), SessionParams{});
  physics::Executor exec(1);
  // Command the hook's hinge to the heart's centre.
  SessionInput in = hook_held_where_it_is(s);
  const Vec3 start = s.stations[1].pose.translation;
  const Vec3 centre = s.scene.layout.heart_centre;
  for (int n = 1; n <= 60; ++n) {
    in.right.pose.translation = start + (centre - start) * (n / 60.0);
    ASSERT_TRUE(step_session(s, in, exec).ok());
    const Vec3 hinge = s.stations[1].pose.translation;
    EXPECT_GE(tissue::heart_signed_distance(s.scene.heart, hinge, 0.01),
              s.params.tool_clearance * (1 - 1e-9));
  }
  EXPECT_TRUE(s.stations[1].touching[static_cast<int>(surgery::Tissue::heart)]);
  bool began = false;
  for (const surgery::Event& e : s.events.events)
    began = began ||
            (e.kind == surgery::EventKind::contact_begin && e.tissue == surgery::Tissue::heart);
  EXPECT_TRUE(began);
}

// The heart beats into an instrument held against it whose shaft runs obliquely to its surface:
// the surface pushes the instrument out along its normal as it comes, step by step, and the
// instrument follows it back, never jumping away (drawn back along its shaft it would leap).
TEST(SurgicalSession, AnInstrumentTheHeartBeatsIntoRidesOnItsSurface) {
  SurgicalSession s = make_surgical_session(scene::default_thorax_scene_params(), SessionParams{});
  ASSERT_TRUE(s.scene.heart.playback.beating);
  physics::Executor exec(1);
  SessionInput in = hook_held_where_it_is(s);
  const Vec3 start = s.stations[1].pose.translation;
  // Beside the vessel, towards the heart and into it.
  const Vec3 target = s.scene.layout.ima_midpoint +
                      Real(0.8) * (s.scene.layout.heart_centre - s.scene.layout.ima_midpoint);
  Real largest_step = 0, largest_heart_step = 0, farthest = 0;
  int pushed = 0;
  Vec3 hinge = start;
  for (int n = 1; n <= 60 + 2 * 160; ++n) {
    in.right.pose.translation = start + (target - start) * std::min(1.0, n / 60.0);
    // The instruments move first in a step, the heart after them (step_session).
    tissue::HeartField heart_then = s.scene.heart;
    const std::vector<Vec3> heart_before = s.scene.heart.current;
    ASSERT_TRUE(step_session(s, in, exec).ok());
    const Vec3 now = s.stations[1].pose.translation;
    if (n > 60) {
      largest_step = std::max(largest_step, (now - hinge).norm());
      for (std::size_t v = 0; v < heart_before.size(); ++v)
        largest_heart_step =
            std::max(largest_heart_step, (s.scene.heart.current[v] - heart_before[v]).norm());
      // The instrument's point nearest the heart (the hinge, the electrode's middle or its tip).
      Real d = std::numeric_limits<Real>::max();
      for (const Vec3& x : probe_points(s.stations[1], s.params.cautery.electrode_length))
        d = std::min(d, tissue::heart_signed_distance(heart_then, x, 0.01));
      EXPECT_GE(d, s.params.tool_clearance * (1 - 1e-6)) << n;
      farthest = std::max(farthest, d);
      pushed += s.stations[1].blocked_by_heart ? 1 : 0;
    }
    hinge = now;
  }
  EXPECT_GT(pushed, 20);  // the heart did move into it
  // It rests on the surface throughout (the clearance is 0.5 mm) and moves with it: the heart's
  // wall moves up to 0.3 mm a step, and sliding over its curve towards the commanded point adds
  // a little. (Drawn back along its shaft it leapt 50 mm and stood 8 mm off.)
  EXPECT_GT(largest_heart_step, 1e-4);
  EXPECT_LT(farthest, 0.001);
  EXPECT_LT(largest_step, 0.002);
}

// A hand that jumps to a pose beyond the heart (a tracker glitch, a clutch released far away):
// the instrument goes as far as the heart lets it and no further, not through it.
TEST(SurgicalSession, AnInstrumentDoesNotPassThroughTheHeart) {
  SurgicalSession s = session_with_a_still_heart();
  physics::Executor exec(1);
  SessionInput in = hook_held_where_it_is(s);
  const Vec3 start = s.stations[1].pose.translation;
  const Vec3 centre = s.scene.layout.heart_centre;
  in.right.pose.translation = centre + Real(0.5) * (centre - start);  // beyond the heart
  for (int n = 0; n < 20; ++n) {
    ASSERT_TRUE(step_session(s, in, exec).ok());
    const Vec3 hinge = s.stations[1].pose.translation;
    EXPECT_GE(tissue::heart_signed_distance(s.scene.heart, hinge, 0.01),
              s.params.tool_clearance * (1 - 1e-6));
    // Still on the near side: nearer the start than the heart's centre is.
    EXPECT_LT((hinge - start).norm(), (centre - start).norm()) << n;
  }
  EXPECT_TRUE(s.stations[1].blocked_by_heart);
}

// The hand presses the hook's device 4 mm past where the heart first stops it, and holds it: the
// heart's rows stop the proxy inside the solve, so the proxy stays out of the heart and the
// surface pushes the tool back with the coupling's spring, k o (what the hand feels, eq. 17).
TEST(SurgicalSession, TheHeartPushesTheProxyBackWithTheCouplingsSpring) {
  SurgicalSession s = session_with_a_still_heart();
  physics::Executor exec(1);
  SessionInput in = hook_held_where_it_is(s);
  const Vec3 start = s.stations[1].pose.translation;
  const Vec3 along = (s.scene.layout.heart_centre - start).normalized();
  Vec3 device = start;
  int n = 0;
  for (; n < 400 && !s.stations[1].blocked_by_heart; ++n) {
    device += Real(0.0002) * along;  // 40 mm/s
    in.right.pose.translation = device;
    ASSERT_TRUE(step_session(s, in, exec).ok());
  }
  ASSERT_TRUE(s.stations[1].blocked_by_heart) << "the hook never reached the heart";
  in.right.pose.translation = device + Real(0.004) * along;
  for (int k = 0; k < 400; ++k)
    ASSERT_TRUE(step_session(s, in, exec).ok());
  const Station& hook = s.stations[1];
  EXPECT_TRUE(hook.blocked_by_heart);
  EXPECT_EQ(hook.stop.tissue, surgery::Tissue::heart);
  for (const Vec3& x : probe_points(hook, s.params.cautery.electrode_length))
    EXPECT_GE(tissue::heart_signed_distance(s.scene.heart, x, 0.01),
              s.params.tool_clearance * (1 - 1e-6));
  // The proxy is held back millimetres from the device, and the force is its spring's, k o,
  // within the coupling's splitting bias: k h / c (2 %, docs/haptics.md).
  const physics::ProxyBody& body = s.scene.patch.world.state.proxies[1];
  EXPECT_GT(hook.proxy.offset.norm(), 0.002);
  EXPECT_LE(hook.proxy.offset.norm(), s.params.proxy.max_offset);
  const physics::Model& model = s.scene.patch.world.model;
  const Real h = model.solver.dt / Real(model.solver.substeps);
  const Vec3 spring = body.stiffness * hook.proxy.offset;
  EXPECT_LT((hook.proxy.tissue_force - spring).norm(),
            body.stiffness * h / body.damping * spring.norm());
  // The heart carries it, pushing out along its normal (the stop's force, all its rows); the rest
  // is the fascia's the electrode also touches: its normal push and friction within its cone.
  EXPECT_GT(hook.stop.force.dot(hook.stop.normal), 0.9 * spring.norm());
  const Vec3 fascia = hook.proxy.tissue_force - hook.stop.force;
  EXPECT_LE((fascia - hook.proxy.normal_force).norm(),
            s.params.proxy.friction[static_cast<std::size_t>(surgery::Tissue::fascia)] *
                hook.proxy.normal_force.norm());
  // Each of the heart's rows rubs within Coulomb's cone over the step, mu its normal impulse.
  const Real mu = s.params.proxy.friction[static_cast<std::size_t>(surgery::Tissue::heart)];
  int touching = 0;
  for (const physics::BodyStopRow& r : s.scene.patch.world.state.body_stops) {
    if (r.body != 1 || r.tag != static_cast<std::uint32_t>(surgery::Tissue::heart)) continue;
    touching += r.normal_impulse > 0 ? 1 : 0;
    EXPECT_LE(r.friction_impulse.norm(), mu * r.normal_impulse * (1 + 1e-9));
  }
  EXPECT_GT(touching, 0);
}

TEST(SurgicalSession, HeatOnTheImaIsRecordedAsInjury) {
  SurgicalSession s = make_surgical_session(scene::default_thorax_scene_params(), SessionParams{});
  physics::Executor exec(1);
  // The hook laid across the vessel: the electrode's middle on the centerline.
  SessionInput in = hook_held_where_it_is(s);
  const Vec3 f = in.right.pose.rotation.col(2);
  in.right.pose.translation =
      s.scene.layout.ima_midpoint - 0.5 * s.params.cautery.electrode_length * f;
  in.right.pedal = surgery::PedalMode::coag;
  in.right.power = 50;
  for (int n = 0; n < 200 && s.events.count(surgery::EventKind::injury) == 0; ++n)
    ASSERT_TRUE(step_session(s, in, exec).ok());
  ASSERT_GE(s.events.count(surgery::EventKind::injury), 1u);
  for (const surgery::Event& e : s.events.events) {
    if (e.kind != surgery::EventKind::injury) continue;
    EXPECT_EQ(e.tissue, surgery::Tissue::ima);
    EXPECT_GE(e.value, s.params.cautery.injury_rise);
    EXPECT_GT(e.count, 0u);
  }
}

// A device lost mid-cut: the instruments hold still and the cautery stops at the
// step the input says so, whatever the lost device's last commands were, and both ends are
// recorded as events; the device's return hands the instruments back.
TEST(SurgicalSession, AnInstrumentWhoseDeviceIsLostHoldsStillWithNoEnergy) {
  const surgery::InputScript script = surgery::load_input_script(kScript);
  SurgicalSession s = make_surgical_session(scene::default_thorax_scene_params(), SessionParams{});
  physics::Executor exec(1);
  tissue::TissueWorld& w = s.scene.patch.world;
  // Into the script's first cut (the pedal is pressed from 0.5 s).
  while (w.state.time < 1.0)
    ASSERT_TRUE(step_session(s, sample_script(script, w.state.time), exec).ok());
  ASSERT_GT(s.fascia_edges_cut, 0u);
  ASSERT_EQ(s.stations[1].pedal, surgery::PedalMode::cut);
  const std::uint64_t cut_before = s.fascia_edges_cut;
  const Real energy_before = s.cautery_energy;
  const Pose hook = s.stations[1].device, forceps = s.stations[0].device;
  // The script goes on cutting and moving both hands; its device is gone.
  while (w.state.time < 1.5) {
    SessionInput in = sample_script(script, w.state.time);
    ASSERT_EQ(in.right.pedal, surgery::PedalMode::cut);
    in.left.device_lost = in.right.device_lost = true;
    ASSERT_TRUE(step_session(s, in, exec).ok());
  }
  EXPECT_EQ(s.fascia_edges_cut, cut_before);
  EXPECT_EQ(s.cautery_energy, energy_before);
  EXPECT_EQ(s.stations[1].pedal, surgery::PedalMode::off);
  EXPECT_EQ(s.stations[1].device.translation, hook.translation);
  EXPECT_EQ(s.stations[0].device.translation, forceps.translation);
  EXPECT_EQ(s.events.count(surgery::EventKind::device_lost), 2u);
  EXPECT_EQ(s.events.count(surgery::EventKind::cautery_off), 1u);
  // Back: the script drives them again.
  for (int n = 0; n < 20; ++n)
    ASSERT_TRUE(step_session(s, sample_script(script, w.state.time), exec).ok());
  EXPECT_EQ(s.events.count(surgery::EventKind::device_restored), 2u);
  EXPECT_NE(s.stations[1].device.translation, hook.translation);
  EXPECT_EQ(s.stations[1].pedal, surgery::PedalMode::cut);
}

}  // namespace
}  // namespace imasim::session
