#pragma once
// A gamepad as a two-handed console, independent of the library that reads it:
//   sticks       each hand's position, as a velocity (full deflection: `speed`), x and y;
//                with its shoulder button held, the stick's y moves the hand in z instead;
//   triggers     each hand's jaw (0 open .. 1 closed, pulled = closed);
//   A / B        the pedal: cut / coagulation while held;
//   X / Y        the left / right clutch while held.
// Every control has its place in GamepadMapping, so a scene file or a user can move it.
#include <array>
#include <cstdint>

#include "devices/hand_input.hpp"

namespace imasim::devices {

// The pad's state as the reader found it: axes in [-1, 1] (triggers [0, 1]), buttons held.
enum GamepadAxis : std::uint8_t { kLeftX, kLeftY, kRightX, kRightY, kLeftTrigger, kRightTrigger };
enum GamepadButton : std::uint8_t {
  kButtonA,
  kButtonB,
  kButtonX,
  kButtonY,
  kLeftShoulder,
  kRightShoulder,
  kGamepadButtons
};

struct GamepadState {
  std::array<Real, 6> axis{};
  std::array<bool, kGamepadButtons> button{};
};

struct GamepadMapping {
  Real speed = Real(0.05);      // hand speed at full deflection (unit: m/s)
  Real dead_zone = Real(0.12);  // |axis| below this is rest (sticks rarely centre exactly)
  Real reach = Real(0.15);      // the hand stays within this of its start per axis (unit: m)
  std::array<std::uint8_t, 2> x_axis{kLeftX, kRightX}, y_axis{kLeftY, kRightY};
  std::array<std::uint8_t, 2> jaw_axis{kLeftTrigger, kRightTrigger};
  std::array<std::uint8_t, 2> depth_button{kLeftShoulder, kRightShoulder};
  std::array<std::uint8_t, 2> clutch_button{kButtonX, kButtonY};
  std::uint8_t cut_button = kButtonA, coag_button = kButtonB;
};

// "a", "b", "x", "y", "left_shoulder", "right_shoulder" (the scene file's names); "?" past them.
const char* gamepad_button_name(std::uint8_t button);

// One update over `dt` seconds: moves each hand, sets jaws, clutches and the pedal. Hands are
// in the console's hand frame (the arms scale them); their velocity is the stick's.
void apply_gamepad(const GamepadMapping& mapping, const GamepadState& pad, Real dt,
                   ConsoleInput& input);

}  // namespace imasim::devices
