#include "devices/gamepad_mapping.hpp"

#include <algorithm>
#include <cmath>

namespace imasim::devices {

namespace {

// Dead zone removed and the rest rescaled to [-1, 1], so a slight push starts slowly.
Real shaped(Real a, Real dead) {
  if (!std::isfinite(a)) return 0;
  a = std::clamp(a, Real(-1), Real(1));
  const Real m = std::abs(a);
  if (m <= dead) return 0;
  return std::copysign((m - dead) / (1 - dead), a);
}

}  // namespace

const char* gamepad_button_name(std::uint8_t button) {
  constexpr const char* kNames[kGamepadButtons] = {
      "a", "b", "x", "y", "left_shoulder", "right_shoulder"};
  return button < kGamepadButtons ? kNames[button] : "?";
}

void apply_gamepad(const GamepadMapping& g, const GamepadState& pad, Real dt, ConsoleInput& in) {
  for (int h = 0; h < 2; ++h) {
    HandInput& hand = in.hand(Hand(h));
    const Real sx = shaped(pad.axis[g.x_axis[h]], g.dead_zone);
    const Real sy = shaped(pad.axis[g.y_axis[h]], g.dead_zone);
    // Stick up (negative y on pads) moves the hand away from the operator (+y, or +z).
    const bool depth = pad.button[g.depth_button[h]];
    const Vec3 velocity = g.speed * Vec3(sx, depth ? 0 : -sy, depth ? -sy : 0);
    hand.frame = PoseFrame::hand;
    hand.velocity = velocity;
    hand.pose.translation = (hand.pose.translation + dt * velocity)
                                .cwiseMax(Vec3::Constant(-g.reach))
                                .cwiseMin(Vec3::Constant(g.reach));
    hand.has_pose = true;
    hand.has_buttons = true;
    hand.jaw = std::clamp(std::isfinite(pad.axis[g.jaw_axis[h]]) ? pad.axis[g.jaw_axis[h]] : 0,
                          Real(0), Real(1));
    hand.clutch = pad.button[g.clutch_button[h]];
  }
  in.pedal = pad.button[g.cut_button]    ? haptics::CauteryMode::cut
             : pad.button[g.coag_button] ? haptics::CauteryMode::coag
                                         : haptics::CauteryMode::off;
}

}  // namespace imasim::devices
