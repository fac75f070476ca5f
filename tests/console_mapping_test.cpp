// The console's input as the session's (console/console_mapping.hpp): hand and tool poses keep
// their frames, a device's jaw value becomes the command that takes the jaws to its angle, the
// pedal and its power drive the hook; and the local model a step publishes puts eq. 17's d at
// the device's depth past the proxy.
#include <gtest/gtest.h>

#include "console/console_mapping.hpp"
#include "console/console_settings_use.hpp"
#include "console/local_model_of.hpp"
#include "scene/thorax_scene.hpp"

namespace imasim::console {
namespace {

const session::SurgicalSession& default_session() {
  static const session::SurgicalSession s =
      session::make_surgical_session(scene::default_thorax_scene_params(), {});
  return s;
}

TEST(ConsoleMapping, PosesKeepTheirFrameAndThePedalDrivesTheHook) {
  const session::SurgicalSession& s = default_session();
  devices::ConsoleInput c;
  session::SessionInput in = to_session_input(c, s);
  EXPECT_EQ(in.left.source, surgery::PoseSource::none);  // nothing arrived yet
  EXPECT_EQ(in.left.jaw, surgery::JawCommand::hold);     // nor any buttons
  c.left.has_pose = true;
  c.left.pose.translation = Vec3(0.01, 0, 0);
  c.right.has_pose = true;
  c.right.frame = devices::PoseFrame::tool;
  c.right.pose.translation = Vec3(0.01, -0.02, 0.06);
  c.right.clutch = true;
  c.pedal = haptics::CauteryMode::coag;
  c.power_w = 25;
  in = to_session_input(c, s);
  EXPECT_EQ(in.left.source, surgery::PoseSource::hand);
  EXPECT_EQ(in.left.pose.translation, Vec3(0.01, 0, 0));
  EXPECT_EQ(in.right.source, surgery::PoseSource::tool);
  EXPECT_TRUE(in.right.clutch);
  EXPECT_EQ(in.right.pedal, surgery::PedalMode::coag);
  EXPECT_EQ(in.right.power, 25);
  EXPECT_EQ(in.left.pedal, surgery::PedalMode::off);
}

TEST(ConsoleMapping, JawValueIsATargetAngle) {
  session::SurgicalSession s = default_session();
  const Real max = s.stations[0].instrument.jaws.max_angle;
  devices::ConsoleInput c;
  c.left.has_buttons = true;
  s.stations[0].state.jaw_angle = 0;  // closed
  c.left.jaw = 0;                     // open wanted
  EXPECT_EQ(to_session_input(c, s).left.jaw, surgery::JawCommand::open);
  s.stations[0].state.jaw_angle = max;
  EXPECT_EQ(to_session_input(c, s).left.jaw, surgery::JawCommand::hold);
  c.left.jaw = 1;  // closed wanted
  EXPECT_EQ(to_session_input(c, s).left.jaw, surgery::JawCommand::close);
  c.left.jaw = 0.5;
  s.stations[0].state.jaw_angle = 0.5 * max + 0.5 * kJawDeadband;
  EXPECT_EQ(to_session_input(c, s).left.jaw, surgery::JawCommand::hold);
}

TEST(LocalModelOf, TheDeviceIsKdDBehindTheProxy) {
  session::SurgicalSession s = default_session();
  session::Station& st = s.stations[1];
  // The hook's proxy held 2 mm short of its device by fascia pushing back along +y while it
  // slides: the drag across the push is eq. 18's to render, so the plane's normal is the push's.
  st.proxy.pressed = surgery::Tissue::fascia;
  st.proxy.tissue_force = Vec3(0.2, 0.6, 0);  // the contacts' friction drags along +x
  st.proxy.normal_force = Vec3(0, 0.6, 0);
  st.source = surgery::PoseSource::tool;
  const haptics::LocalModel m = local_model_of(s, 1, 2.0, 7);
  ASSERT_EQ(m.contact_count, 1u);
  EXPECT_EQ(m.contacts[0].tissue, haptics::TissueKind::fascia);
  EXPECT_EQ(m.contacts[0].normal, Vec3::UnitY());
  EXPECT_EQ(m.time_s, 2.0);
  const Vec3 proxy = st.state.controller.translation;
  const haptics::DeviceTip device =
      haptics::device_in_scene(m, proxy - Vec3(0, 0.002, 0), Vec3::Zero());
  const haptics::ForceModelParams law = haptics::default_force_model_params();
  const haptics::ForceChannels f = haptics::evaluate_local_model(m, law, device, 2.0);
  EXPECT_NEAR(f.normal.y(), law.of(haptics::TissueKind::fascia).stiffness * 0.002, 1e-12);
  // A hand pose goes through the arm's scaling: 6 mm of hand is 2 mm of tool.
  st.source = surgery::PoseSource::hand;
  const haptics::LocalModel h = local_model_of(s, 1, 2.0, 7);
  EXPECT_NEAR(h.motion_scale, 1.0 / 3.0, 1e-12);
  const Vec3 hand = st.arm_state.hand_anchor.translation +
                    3 * (proxy - st.arm_state.tool_anchor.translation) - Vec3(0, 0.006, 0);
  const haptics::ForceChannels g =
      haptics::evaluate_local_model(h, law, haptics::device_in_scene(h, hand, Vec3::Zero()), 2.0);
  EXPECT_NEAR(g.normal.y(), law.of(haptics::TissueKind::fascia).stiffness * 0.002, 1e-9);
}

// Stopped against the beating heart: the local model's heart contact moves with the wall, so
// between steps the depth (and eq. 17's force) follows the wall's motion toward the device.
TEST(LocalModelOf, TheHeartsContactMovesWithItsWall) {
  session::SurgicalSession s = default_session();
  session::Station& st = s.stations[0];
  st.source = surgery::PoseSource::tool;
  const Vec3 hinge = st.state.controller.translation;
  st.stop.tissue = surgery::Tissue::heart;
  st.stop.point = st.stop.plane = hinge + Vec3(0, 0, 0.004);  // the jaws' tip, 4 mm past the hinge
  st.stop.normal = -Vec3::UnitY();
  st.stop.velocity = Vec3(0.01, -0.03, 0);  // the wall coming at the tool at 30 mm/s
  const haptics::LocalModel m = local_model_of(s, 0, 1.0, 3);
  ASSERT_EQ(m.contact_count, 1u);
  EXPECT_EQ(m.contacts[0].tissue, haptics::TissueKind::heart);
  EXPECT_EQ(m.contacts[0].surface_velocity, st.stop.velocity);
  // The device 1 mm past the stop (into the heart, +y), still: after 2 ms the wall has come
  // 0.06 mm further at it.
  const haptics::DeviceTip device =
      haptics::device_in_scene(m, hinge + Vec3(0, 0.001, 0), Vec3::Zero());
  const haptics::ForceModelParams law = haptics::default_force_model_params();
  const haptics::ContactForceParams heart = law.of(haptics::TissueKind::heart);
  const haptics::ForceChannels f = haptics::evaluate_local_model(m, law, device, 1.002);
  // eq. 17: k_d d + c_d v_n, d = 1.06 mm, v_n = 30 mm/s (the wall's speed into the device).
  EXPECT_NEAR(f.normal_n, heart.stiffness * 0.00106 + heart.damping * 0.03, 1e-9);
  EXPECT_NEAR(f.normal.normalized().dot(-Vec3::UnitY()), 1.0, 1e-12);
}

// The forceps hold tissue that pulls them along +y while the heart stops them: the spring k o
// carries both. The hand feels the pull once, at the fascia's k_d whatever the coupling's k, and
// the heart at its own k_d at the device's depth past where it stops the proxy (the pull's share
// rendered at k_d / k of the offset would be felt k_d / k times; the heart's at the spring's, the
// coupling's k instead of the heart's).
TEST(LocalModelOf, ThePullIsFeltOnceAndTheHeartAtItsOwnKd) {
  session::SurgicalSession s = default_session();
  session::Station& st = s.stations[0];
  st.source = surgery::PoseSource::tool;
  const Vec3 hinge = st.state.controller.translation;
  const Vec3 heart_normal = Vec3(0, 0.8, 0.6);
  const Vec3 pull(0, 0.3, 0);
  const haptics::ForceModelParams law = haptics::default_force_model_params();
  const Real heart_k = law.of(haptics::TissueKind::heart).stiffness;
  const Real fascia_k = law.of(haptics::TissueKind::fascia).stiffness;
  ASSERT_EQ(s.params.proxy.stiffness[std::size_t(surgery::Tissue::fascia)], fascia_k);
  ASSERT_EQ(s.params.proxy.stiffness[std::size_t(surgery::Tissue::heart)], heart_k);
  for (const Real k : {Real(300), Real(1000)}) {
    // The device 1 mm past the heart's stop along its normal, and the pull's stretch of the
    // spring: the heart carries the rest of k o, plus a little friction.
    st.proxy.offset = 0.001 * heart_normal + pull / k;
    st.proxy.coupling = k;
    st.proxy.pressed = surgery::Tissue::fascia;
    st.proxy.normal_force = pull;
    const Vec3 heart = k * 0.001 * heart_normal + Vec3(0.01, 0, 0);
    st.proxy.tissue_force = pull + heart;
    st.stop.tissue = surgery::Tissue::heart;
    st.stop.point = st.stop.plane = hinge + Vec3(0, 0, 0.004);
    st.stop.normal = heart_normal;
    st.stop.force = heart;
    const haptics::LocalModel m = local_model_of(s, 0, 1.0, 3);
    ASSERT_EQ(m.contact_count, 2u);
    const haptics::DeviceTip device =
        haptics::device_in_scene(m, hinge - st.proxy.offset, Vec3::Zero());
    const haptics::ForceChannels f = haptics::evaluate_local_model(m, law, device, 1.0);
    const Real heart_depth = st.proxy.offset.dot(heart_normal);
    const Vec3 normal = pull + heart_k * heart_depth * heart_normal;
    EXPECT_NEAR((f.normal - normal).norm(), 0, 1e-12) << k;
    // A millimetre further on (-y), each plane's depth grows by the device's motion along it.
    const haptics::DeviceTip further =
        haptics::device_in_scene(m, hinge - st.proxy.offset - Vec3(0, 0.001, 0), Vec3::Zero());
    const haptics::ForceChannels g = haptics::evaluate_local_model(m, law, further, 1.0);
    EXPECT_NEAR((g.normal - normal).norm(),
                (fascia_k * 0.001 * Vec3::UnitY() + heart_k * 0.0008 * heart_normal).norm(), 1e-12)
        << k;
  }
}

// The scene file's console defaults are the haptics' and devices' own (one table each side).
TEST(ConsoleSettings, DefaultsAreTheLayersOwn) {
  const scene::ConsoleSettings c = scene::default_console_settings();
  const haptics::ForceModelParams a = force_model_params(c);
  const haptics::ForceModelParams b = haptics::default_force_model_params();
  for (std::size_t k = 0; k < haptics::kTissueKinds; ++k) {
    EXPECT_EQ(a.contact[k].stiffness, b.contact[k].stiffness) << k;
    EXPECT_EQ(a.contact[k].damping, b.contact[k].damping) << k;
    EXPECT_EQ(a.contact[k].friction, b.contact[k].friction) << k;
    EXPECT_EQ(a.contact[k].cutting_resistance, b.contact[k].cutting_resistance) << k;
    EXPECT_EQ(a.thermal_cut[k].coefficient, b.thermal_cut[k].coefficient) << k;
    EXPECT_EQ(a.thermal_cut[k].decay, b.thermal_cut[k].decay) << k;
    EXPECT_EQ(a.thermal_coag[k].coefficient, b.thermal_coag[k].coefficient) << k;
    EXPECT_EQ(a.thermal_coag[k].decay, b.thermal_coag[k].decay) << k;
  }
  const haptics::SafetyParams s = safety_params(c), d;
  EXPECT_EQ(s.device_max_force, d.device_max_force);
  EXPECT_EQ(s.max_rate, d.max_rate);
  EXPECT_EQ(s.ramp_s, Real(d.ramp_s));
  EXPECT_EQ(s.stale_after_s, Real(d.stale_after_s));
  EXPECT_EQ(s.fade_s, Real(d.fade_s));
  EXPECT_EQ(live_console_params(c).tremor.cutoff_hz, devices::TremorFilterParams{}.cutoff_hz);
  const devices::IgtlDeviceConfig link = igtl_device_config(c);
  const devices::IgtlNames names;
  EXPECT_EQ(link.link.names.left_pose, names.left_pose);
  EXPECT_EQ(link.link.names.right_force, names.right_force);
  EXPECT_EQ(link.link.names.pedal, names.pedal);
  EXPECT_EQ(link.link.port, devices::IgtlLinkConfig{}.port);
  EXPECT_EQ(link.link.address, devices::IgtlLinkConfig{}.address);
  EXPECT_EQ(c.motion_scale, surgery::ArmParams{}.motion_scale);
}

// The scene file's device mappings default to the devices' own and reach them when changed.
TEST(ConsoleSettings, DeviceMappingsAreTheDevicesOwnAndFollowTheSceneFile) {
  scene::ConsoleSettings c = scene::default_console_settings();
  const devices::GamepadMapping g = gamepad_mapping(c), gd;
  EXPECT_EQ(g.speed, gd.speed);
  EXPECT_EQ(g.dead_zone, gd.dead_zone);
  EXPECT_EQ(g.reach, gd.reach);
  EXPECT_EQ(g.cut_button, gd.cut_button);
  EXPECT_EQ(g.coag_button, gd.coag_button);
  EXPECT_EQ(g.clutch_button, gd.clutch_button);
  const devices::SpaceMouseMapping m = spacemouse_mapping(c), md;
  EXPECT_EQ(m.hand, md.hand);
  EXPECT_EQ(m.speed, md.speed);
  EXPECT_EQ(m.turn_rate, md.turn_rate);
  EXPECT_EQ(m.dead_zone, md.dead_zone);
  EXPECT_EQ(m.jaw_button, md.jaw_button);
  EXPECT_EQ(m.clutch_button, md.clutch_button);
  const devices::PedalMapping p = pedal_mapping(c), pd;
  EXPECT_EQ(p.joystick, pd.joystick);
  EXPECT_EQ(p.cut_button, pd.cut_button);
  EXPECT_EQ(p.coag_button, pd.coag_button);
  EXPECT_EQ(p.clutch_button, pd.clutch_button);

  c.gamepad_cut_button = "right_shoulder";
  c.gamepad_left_clutch_button = "a";
  c.spacemouse_hand = "left";
  c.pedal_clutch_button = scene::kUnmappedPedalButton;
  EXPECT_EQ(gamepad_mapping(c).cut_button, devices::kRightShoulder);
  EXPECT_EQ(gamepad_mapping(c).clutch_button[0], devices::kButtonA);
  EXPECT_EQ(spacemouse_mapping(c).hand, devices::Hand::left);
  EXPECT_EQ(pedal_mapping(c).clutch_button, devices::kNoPedalButton);
}

}  // namespace
}  // namespace imasim::console
