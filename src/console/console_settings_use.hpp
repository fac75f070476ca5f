#pragma once
// A scene file's console settings (scene/console_settings.hpp) as the haptics' and devices' own
// parameters: the force model, the safety filter, the tremor filter, the OpenIGTLink link.
#include "console/live_console.hpp"
#include "devices/gamepad_mapping.hpp"
#include "devices/igtl_device.hpp"
#include "devices/pedal_mapping.hpp"
#include "devices/spacemouse_device.hpp"
#include "scene/console_settings.hpp"

namespace imasim::console {

haptics::ForceModelParams force_model_params(const scene::ConsoleSettings& settings);
haptics::SafetyParams safety_params(const scene::ConsoleSettings& settings);
LiveConsoleParams live_console_params(const scene::ConsoleSettings& settings);
// The link as the scene file describes it (the role and any command-line overrides are the
// caller's).
devices::IgtlDeviceConfig igtl_device_config(const scene::ConsoleSettings& settings);
// devices.tracker_translation_m and tracker_rotation_deg as the pose of the tracker's frame in
// the scene.
Pose tracker_to_scene(const scene::ConsoleSettings& settings);
devices::GamepadMapping gamepad_mapping(const scene::ConsoleSettings& settings);
devices::SpaceMouseMapping spacemouse_mapping(const scene::ConsoleSettings& settings);
devices::PedalMapping pedal_mapping(const scene::ConsoleSettings& settings);

}  // namespace imasim::console
