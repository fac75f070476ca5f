// Foot pedals (devices/pedal_mapping.hpp, devices/joystick_pedal_device.hpp): a joystick's
// buttons press the cautery's pedals and the clutch as the mapping says; through SDL2 a virtual
// joystick (no hardware, no display) does the same, and pulling it out lifts every pedal.
#include <SDL2/SDL.h>
#include <gtest/gtest.h>

#include <array>

#include "devices/joystick_pedal_device.hpp"
#include "virtual_joystick.hpp"

namespace imasim::devices {
namespace {

TEST(PedalMapping, ButtonsPressTheirPedalsCutWinsAndClutchBothHands) {
  PedalMapping m;  // cut 0, coag 1, clutch 2
  std::array<bool, 4> held{};
  ConsoleInput in;
  held[1] = true;
  apply_pedals(m, held, in);
  EXPECT_EQ(in.pedal, haptics::CauteryMode::coag);
  EXPECT_FALSE(in.left.clutch);
  held[0] = true;  // both: cut
  held[2] = true;
  apply_pedals(m, held, in);
  EXPECT_EQ(in.pedal, haptics::CauteryMode::cut);
  EXPECT_TRUE(in.left.clutch);
  EXPECT_TRUE(in.right.clutch);
  held = {};
  apply_pedals(m, held, in);
  EXPECT_EQ(in.pedal, haptics::CauteryMode::off);
  EXPECT_FALSE(in.right.clutch);
}

TEST(PedalMapping, RemappedUnmappedAndMissingButtons) {
  PedalMapping m;
  m.cut_button = 3;
  m.coag_button = 7;  // the switch has only 4 buttons: never pressed
  m.clutch_button = kNoPedalButton;
  std::array<bool, 4> held{};
  ConsoleInput in;
  in.left.clutch = true;  // another device's clutch is left alone
  held[3] = true;
  held[2] = true;
  apply_pedals(m, held, in);
  EXPECT_EQ(in.pedal, haptics::CauteryMode::cut);
  EXPECT_TRUE(in.left.clutch);
  EXPECT_FALSE(in.right.clutch);
  release_pedals(m, in);
  EXPECT_EQ(in.pedal, haptics::CauteryMode::off);
  EXPECT_TRUE(in.left.clutch);
}

TEST(PedalMapping, JoystickNames) {
  EXPECT_TRUE(joystick_name_matches("any", "VEC USB Footpedal", false));
  EXPECT_FALSE(joystick_name_matches("any", "Xbox Wireless Controller", true));
  EXPECT_TRUE(joystick_name_matches("footpedal", "VEC USB Footpedal", false));
  EXPECT_TRUE(joystick_name_matches("Xbox", "Xbox Wireless Controller", true));
  EXPECT_FALSE(joystick_name_matches("pedal", "Xbox Wireless Controller", true));
}

TEST(JoystickPedalDevice, AVirtualFootSwitchThroughSdlPressesThePedals) {
  // A plain HID joystick, as foot switches are.
  test::VirtualJoystick stick("imasim test foot switch", false, 3);
  ASSERT_TRUE(stick.attached()) << SDL_GetError();
  {
    PedalMapping m;
    m.joystick = "Foot Switch";  // any part of the name, any case
    JoystickPedalDevice pedal(m);
    ASSERT_TRUE(pedal.connected());
    EXPECT_EQ(pedal.info().name, "imasim test foot switch");
    EXPECT_TRUE(pedal.info().drives_pedal);
    ConsoleInput in;
    stick.set_button(1, true);
    pedal.poll(0.0, in);
    EXPECT_EQ(in.pedal, haptics::CauteryMode::coag);
    stick.set_button(2, true);
    pedal.poll(0.001, in);
    EXPECT_TRUE(in.left.clutch && in.right.clutch);
    // Pulled out with a foot on the pedals: no energy, no clutch.
    stick.unplug();
    pedal.poll(0.002, in);
    EXPECT_FALSE(pedal.connected());
    EXPECT_EQ(in.pedal, haptics::CauteryMode::off);
    EXPECT_FALSE(in.left.clutch || in.right.clutch);
  }
  {
    PedalMapping m;
    m.joystick = "no such pedal";
    const JoystickPedalDevice absent(m);
    EXPECT_FALSE(absent.connected());
  }
}

}  // namespace
}  // namespace imasim::devices
