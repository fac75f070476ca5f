#pragma once
// The console's settings as a scene file gives them: the force model's parameters
// per tissue (eq. 17-19, docs/haptics.md for their reasoning), the safety limits, the hands'
// motion scaling and tremor filter, and the OpenIGTLink link (address, port, device names).
// Plain numbers and names here; the console layer turns them into the haptics' and devices'
// own parameters (console/console_settings_use.hpp), whose defaults these equal (tested).
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "math/types.hpp"

namespace imasim::scene {

// One tissue's force parameters (eq. 17-19).
struct TissueForceSettings {
  Real stiffness = 0;           // k_d (unit: N/m)
  Real damping = 0;             // c_d (unit: N s/m)
  Real friction = 0;            // mu (-)
  Real cutting_resistance = 0;  // k_c of eq. 18 (unit: N s/m)
  Real cut_coefficient = 0;     // k_t while cutting (unit: N/W)
  Real cut_decay = 0;           // alpha while cutting (unit: 1/m)
  Real coag_coefficient = 0;    // k_t while coagulating (unit: N/W)
  Real coag_decay = 0;          // alpha while coagulating (unit: 1/m)
};

// Tissues in the force model's order: fascia, fat, IMA, heart, chest wall.
inline constexpr std::array<const char*, 5> kForceTissueNames = {"fascia", "fat", "ima", "heart",
                                                                 "chest_wall"};

// The gamepad buttons a function can be given, in devices::GamepadButton's order.
inline constexpr std::array<std::string_view, 6> kGamepadButtonNames = {
    "a", "b", "x", "y", "left_shoulder", "right_shoulder"};
inline constexpr std::array<std::string_view, 2> kHandNames = {"left", "right"};
inline constexpr std::array<std::string_view, 2> kToolRegistrations = {"fixed", "clutch"};
// A foot-switch button number meaning "not mapped".
inline constexpr std::uint32_t kUnmappedPedalButton = 32;

struct ConsoleSettings {
  std::array<TissueForceSettings, 5> force;
  // The tool proxy's coupling to the device, one for every tissue (surgery/tool_proxy.hpp).
  Real proxy_stiffness = 1000;        // (unit: N/m)
  Real proxy_damping = 5;             // (unit: N s/m)
  Real device_max_force = Real(3.3);  // (unit: N)
  Real max_force_rate = 500;          // (unit: N/s)
  Real ramp_s = Real(0.5);            // force ramp-in after start and clutch (unit: s)
  Real stale_after_s = Real(0.02);    // the watchdog's limit on the local model's age (unit: s)
  Real fade_s = Real(0.01);           // (unit: s)
  Real motion_scale = Real(1) / 3;    // instrument motion per hand motion (-)
  Real tremor_cutoff_hz = 6;          // 0: no tremor filter (unit: Hz)
  std::string igtl_address = "127.0.0.1";
  std::uint32_t igtl_port = 18944;
  bool igtl_allow_remote = false;
  Real igtl_idle_timeout_s = 5;  // a peer silent this long is dropped; 0: never (unit: s)
  // The tracker's frame in the scene: every OpenIGTLink pose is turned by the rotation (x, then
  // y, then z, about the scene's axes) and moved by the translation (unit: m, deg).
  Vec3 tracker_translation = Vec3::Zero();
  Vec3 tracker_rotation_deg = Vec3::Zero();
  // Tool poses: "fixed" placed where the tracker says; "clutch" moved by how far the tracker moved
  // since the clutch was last released (registered at the first pose and at each release).
  std::string tool_registration = "fixed";
  std::string left_hand = "LeftHand", right_hand = "RightHand";
  std::string left_tool = "LeftTool", right_tool = "RightTool";
  std::string left_buttons = "LeftButtons", right_buttons = "RightButtons";
  std::string pedal = "Pedal";
  std::string left_force = "LeftForce", right_force = "RightForce";
  // Gamepad (SDL2): sticks move the hands as velocities; these buttons are named above.
  Real gamepad_speed = Real(0.05);      // at full deflection (unit: m/s)
  Real gamepad_dead_zone = Real(0.12);  // share of the stick's travel read as rest (-)
  Real gamepad_reach = Real(0.15);      // a hand's range from its start per axis (unit: m)
  std::string gamepad_cut_button = "a", gamepad_coag_button = "b";
  std::string gamepad_left_clutch_button = "x", gamepad_right_clutch_button = "y";
  // 3D mouse (spacenavd): one hand.
  std::string spacemouse_hand = "right";
  Real spacemouse_speed = Real(0.04);     // at full push (unit: m/s)
  Real spacemouse_turn_rate = Real(1.0);  // at full twist (unit: rad/s)
  Real spacemouse_dead_zone = Real(0.05);
  std::uint32_t spacemouse_jaw_button = 0, spacemouse_clutch_button = 1;
  // Foot pedals: a joystick's buttons (a USB foot switch).
  std::string pedal_joystick = "any";  // a part of its name, or "any" non-gamepad joystick
  std::uint32_t pedal_cut_button = 0, pedal_coag_button = 1, pedal_clutch_button = 2;
};

ConsoleSettings default_console_settings();

}  // namespace imasim::scene
