// Gamepads (devices/gamepad_mapping.hpp, devices/gamepad_device.hpp): the mapping moves each
// hand at the stick's speed, past a dead zone, within its reach, and sets jaws, clutches and the
// pedal; through SDL2 a virtual game controller (no hardware, no display) drives it the same.
#include <SDL2/SDL.h>
#include <gtest/gtest.h>

#include "devices/gamepad_device.hpp"
#include "virtual_joystick.hpp"

namespace imasim::devices {
namespace {

TEST(GamepadMapping, SticksMoveTheHandsAtTheirSpeed) {
  const GamepadMapping g;
  GamepadState pad;
  ConsoleInput in;
  pad.axis[kLeftX] = 1;      // full right
  pad.axis[kRightY] = -0.5;  // half up
  for (int k = 0; k < 100; ++k)
    apply_gamepad(g, pad, Real(0.01), in);  // 1 s
  EXPECT_NEAR(in.left.pose.translation.x(), g.speed, 1e-12);
  EXPECT_NEAR(in.left.velocity.x(), g.speed, 1e-12);
  const Real half = (Real(0.5) - g.dead_zone) / (1 - g.dead_zone);
  EXPECT_NEAR(in.right.pose.translation.y(), g.speed * half, 1e-12);
  EXPECT_EQ(in.right.pose.translation.z(), 0);
  // With the shoulder held the stick's y moves the hand in depth.
  pad.button[kRightShoulder] = true;
  apply_gamepad(g, pad, Real(0.1), in);
  EXPECT_NEAR(in.right.pose.translation.z(), g.speed * half * 0.1, 1e-12);
  // A stick resting slightly off centre does not drift; the reach bounds the hand.
  GamepadState rest;
  rest.axis[kLeftX] = g.dead_zone * Real(0.9);
  const Vec3 before = in.left.pose.translation;
  apply_gamepad(g, rest, Real(1), in);
  EXPECT_EQ(in.left.pose.translation, before);
  pad.axis[kLeftX] = 1;
  apply_gamepad(g, pad, Real(100), in);
  EXPECT_EQ(in.left.pose.translation.x(), g.reach);
  // A non-finite axis (a broken driver) is rest.
  GamepadState broken;
  broken.axis[kLeftY] = NAN;
  broken.axis[kLeftTrigger] = NAN;
  apply_gamepad(g, broken, Real(0.1), in);
  EXPECT_TRUE(in.left.pose.translation.allFinite());
  EXPECT_EQ(in.left.jaw, 0);
}

TEST(GamepadMapping, TriggersButtonsAndPedal) {
  const GamepadMapping g;
  GamepadState pad;
  ConsoleInput in;
  pad.axis[kLeftTrigger] = 0.75;
  pad.button[kButtonY] = true;
  pad.button[kButtonB] = true;
  apply_gamepad(g, pad, Real(0.01), in);
  EXPECT_EQ(in.left.jaw, Real(0.75));
  EXPECT_TRUE(in.left.has_buttons);
  EXPECT_FALSE(in.left.clutch);
  EXPECT_TRUE(in.right.clutch);
  EXPECT_EQ(in.pedal, haptics::CauteryMode::coag);
  pad.button[kButtonA] = true;  // cut wins over coagulation
  apply_gamepad(g, pad, Real(0.01), in);
  EXPECT_EQ(in.pedal, haptics::CauteryMode::cut);
}

TEST(GamepadDevice, AVirtualControllerThroughSdlDrivesTheHands) {
  test::VirtualJoystick stick("imasim test pad", true);
  ASSERT_TRUE(stick.attached()) << SDL_GetError();
  {
    GamepadDevice pad;
    ASSERT_TRUE(pad.connected());
    EXPECT_EQ(pad.info().name, "imasim test pad");
    stick.set_axis(SDL_CONTROLLER_AXIS_LEFTX, 32767);
    stick.set_axis(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 32767);
    stick.set_button(SDL_CONTROLLER_BUTTON_A, true);
    ConsoleInput in;
    for (int k = 0; k <= 50; ++k)
      pad.poll(k * 0.01, in);  // 0.5 s
    EXPECT_NEAR(in.left.pose.translation.x(), 0.5 * GamepadMapping{}.speed, 1e-9);
    EXPECT_NEAR(in.right.jaw, 1, 1e-9);
    EXPECT_EQ(in.pedal, haptics::CauteryMode::cut);
    pad.send_force(Hand::left, Vec3(1, 0, 0), 1.0);  // a rumble; a virtual pad ignores it
    // Unplugged: no longer connected, the hands stay where they were.
    stick.unplug();
    const Vec3 left = in.left.pose.translation;
    pad.poll(0.6, in);
    EXPECT_FALSE(pad.connected());
    EXPECT_EQ(in.left.pose.translation, left);
    EXPECT_EQ(in.pedal, haptics::CauteryMode::off);  // no energy without the pad
    EXPECT_EQ(in.left.velocity, Vec3::Zero());
  }
}

}  // namespace
}  // namespace imasim::devices
