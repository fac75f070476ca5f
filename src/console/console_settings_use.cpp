#include "console/console_settings_use.hpp"

namespace imasim::console {

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

devices::IgtlDeviceConfig igtl_device_config(const scene::ConsoleSettings& c) {
  devices::IgtlDeviceConfig d;
  d.link.address = c.igtl_address;
  d.link.port = static_cast<std::uint16_t>(c.igtl_port);
  d.link.allow_remote = c.igtl_allow_remote;
  devices::IgtlNames& n = d.link.names;
  n.left_pose = c.left_hand, n.right_pose = c.right_hand;
  n.left_tool = c.left_tool, n.right_tool = c.right_tool;
  n.left_buttons = c.left_buttons, n.right_buttons = c.right_buttons;
  n.pedal = c.pedal;
  n.left_force = c.left_force, n.right_force = c.right_force;
  d.max_force_n = c.device_max_force;
  return d;
}

}  // namespace imasim::console
