#include "console/console_settings_use.hpp"

#include <Eigen/Geometry>
#include <numbers>

namespace imasim::console {

namespace {

// The scene file's button names are kGamepadButtonNames, in devices::GamepadButton's order.
static_assert(devices::kButtonA == 0 && devices::kButtonB == 1 && devices::kButtonX == 2 &&
              devices::kButtonY == 3 && devices::kLeftShoulder == 4 &&
              devices::kRightShoulder == 5 &&
              devices::kGamepadButtons == scene::kGamepadButtonNames.size());
static_assert(devices::kNoPedalButton == scene::kUnmappedPedalButton);

// A name the scene file checked against kGamepadButtonNames; an unknown one (a settings object
// built by hand) keeps the default.
std::uint8_t gamepad_button(const std::string& name, std::uint8_t fallback) {
  for (std::size_t k = 0; k < scene::kGamepadButtonNames.size(); ++k)
    if (scene::kGamepadButtonNames[k] == name) return static_cast<std::uint8_t>(k);
  return fallback;
}

}  // namespace

haptics::ForceModelParams force_model_params(const scene::ConsoleSettings& c) {
  haptics::ForceModelParams p;
  for (std::size_t k = 0; k < haptics::kTissueKinds; ++k) {
    const scene::TissueForceSettings& f = c.force[k];
    p.contact[k] = {f.stiffness, f.damping, f.friction, f.cutting_resistance};
    p.thermal_cut[k] = {f.cut_coefficient, f.cut_decay};
    p.thermal_coag[k] = {f.coag_coefficient, f.coag_decay};
  }
  return p;
}

haptics::SafetyParams safety_params(const scene::ConsoleSettings& c) {
  haptics::SafetyParams s;
  s.device_max_force = c.device_max_force;
  s.max_rate = c.max_force_rate;
  s.ramp_s = c.ramp_s;
  s.stale_after_s = c.stale_after_s;
  s.fade_s = c.fade_s;
  return s;
}

LiveConsoleParams live_console_params(const scene::ConsoleSettings& c) {
  LiveConsoleParams p;
  p.forces = force_model_params(c);
  p.safety = safety_params(c);
  p.tremor.cutoff_hz = c.tremor_cutoff_hz;
  return p;
}

Pose tracker_to_scene(const scene::ConsoleSettings& c) {
  const Vec3 a = c.tracker_rotation_deg * (std::numbers::pi_v<Real> / 180);
  Pose p;
  // About x, then y, then z, about the scene's fixed axes.
  p.rotation =
      (Eigen::AngleAxis<Real>(a.z(), Vec3::UnitZ()) * Eigen::AngleAxis<Real>(a.y(), Vec3::UnitY()) *
       Eigen::AngleAxis<Real>(a.x(), Vec3::UnitX()))
          .toRotationMatrix();
  p.translation = c.tracker_translation;
  return p;
}

devices::IgtlDeviceConfig igtl_device_config(const scene::ConsoleSettings& c) {
  devices::IgtlDeviceConfig d;
  d.link.address = c.igtl_address;
  d.link.port = static_cast<std::uint16_t>(c.igtl_port);
  d.link.allow_remote = c.igtl_allow_remote;
  d.link.idle_timeout_s = double(c.igtl_idle_timeout_s);
  d.link.tracker_to_scene = tracker_to_scene(c);
  devices::IgtlNames& n = d.link.names;
  n.left_pose = c.left_hand, n.right_pose = c.right_hand;
  n.left_tool = c.left_tool, n.right_tool = c.right_tool;
  n.left_buttons = c.left_buttons, n.right_buttons = c.right_buttons;
  n.pedal = c.pedal;
  n.left_force = c.left_force, n.right_force = c.right_force;
  d.max_force_n = c.device_max_force;
  return d;
}

devices::GamepadMapping gamepad_mapping(const scene::ConsoleSettings& c) {
  devices::GamepadMapping g;
  g.speed = c.gamepad_speed;
  g.dead_zone = c.gamepad_dead_zone;
  g.reach = c.gamepad_reach;
  g.cut_button = gamepad_button(c.gamepad_cut_button, g.cut_button);
  g.coag_button = gamepad_button(c.gamepad_coag_button, g.coag_button);
  g.clutch_button[0] = gamepad_button(c.gamepad_left_clutch_button, g.clutch_button[0]);
  g.clutch_button[1] = gamepad_button(c.gamepad_right_clutch_button, g.clutch_button[1]);
  return g;
}

devices::SpaceMouseMapping spacemouse_mapping(const scene::ConsoleSettings& c) {
  devices::SpaceMouseMapping m;
  m.hand = c.spacemouse_hand == "left" ? devices::Hand::left : devices::Hand::right;
  m.speed = c.spacemouse_speed;
  m.turn_rate = c.spacemouse_turn_rate;
  m.dead_zone = c.spacemouse_dead_zone;
  m.jaw_button = int(c.spacemouse_jaw_button);
  m.clutch_button = int(c.spacemouse_clutch_button);
  return m;
}

devices::PedalMapping pedal_mapping(const scene::ConsoleSettings& c) {
  devices::PedalMapping p;
  p.joystick = c.pedal_joystick;
  p.cut_button = c.pedal_cut_button;
  p.coag_button = c.pedal_coag_button;
  p.clutch_button = c.pedal_clutch_button;
  return p;
}

}  // namespace imasim::console
