#pragma once
// Foot pedals as joystick buttons: a USB foot switch reads as a joystick whose
// buttons are the pedals. Which button is which is the scene file's (devices.pedal_*): the
// cautery's cut and coagulation pedals (energy while held; cut wins when both are held) and a
// clutch pedal that clutches both hands while held, as on a robotic console.
#include <cstdint>
#include <span>
#include <string>

#include "devices/hand_input.hpp"

namespace imasim::devices {

inline constexpr std::uint32_t kNoPedalButton = 32;  // a pedal function left unmapped

struct PedalMapping {
  // The joystick used: the first whose name contains this (case-insensitive), "any" for the
  // first joystick that is not a game controller.
  std::string joystick = "any";
  std::uint32_t cut_button = 0, coag_button = 1, clutch_button = 2;  // kNoPedalButton: none
};

// Sets the pedal (and, if mapped, both hands' clutches) from the buttons held. A button the
// joystick does not have reads as released.
void apply_pedals(const PedalMapping& mapping, std::span<const bool> held, ConsoleInput& input);

// What the console falls back to when the pedals are lost: no energy, no clutch held.
void release_pedals(const PedalMapping& mapping, ConsoleInput& input);

}  // namespace imasim::devices
