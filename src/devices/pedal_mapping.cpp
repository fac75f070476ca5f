#include "devices/pedal_mapping.hpp"

namespace imasim::devices {

namespace {

bool pressed(std::span<const bool> held, std::uint32_t button) {
  return button < held.size() && held[button];
}

}  // namespace

void apply_pedals(const PedalMapping& m, std::span<const bool> held, ConsoleInput& input) {
  input.pedal = pressed(held, m.cut_button)    ? haptics::CauteryMode::cut
                : pressed(held, m.coag_button) ? haptics::CauteryMode::coag
                                               : haptics::CauteryMode::off;
  if (m.clutch_button == kNoPedalButton) return;
  const bool clutch = pressed(held, m.clutch_button);
  input.left.clutch = clutch;
  input.right.clutch = clutch;
}

void release_pedals(const PedalMapping& m, ConsoleInput& input) {
  input.pedal = haptics::CauteryMode::off;
  if (m.clutch_button == kNoPedalButton) return;
  input.left.clutch = false;
  input.right.clutch = false;
}

}  // namespace imasim::devices
