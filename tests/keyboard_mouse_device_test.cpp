// The keyboard and mouse as a console (ui/keyboard_mouse_device.hpp): held keys move each hand
// at the mapping's speed within its reach, jaw keys integrate the jaws, clutch and pedal keys
// hold, power keys step within the generator's range, drags move a hand by their pixels; the
// device does the same from its key state (no window needed).
#include <gtest/gtest.h>

#include <cmath>

#include "ui/key_bindings.hpp"
#include "ui/keyboard_mouse_device.hpp"

namespace imasim::ui {
namespace {

TEST(KeyboardMapping, HeldKeysMoveEachHandAtItsSpeed) {
  const KeyboardMapping m;
  devices::ConsoleInput in;
  const KeySet held =
      bit(Control::left_x_plus) | bit(Control::right_y_plus) | bit(Control::right_z_minus);
  for (int k = 0; k < 100; ++k)
    apply_keyboard(m, held, {}, 0.01, in);  // 1 s
  EXPECT_NEAR(in.left.pose.translation.x(), m.speed, 1e-12);
  EXPECT_EQ(in.left.pose.translation.y(), 0);
  EXPECT_NEAR(in.left.velocity.x(), m.speed, 1e-12);
  EXPECT_NEAR(in.right.pose.translation.y(), m.speed, 1e-12);
  EXPECT_NEAR(in.right.pose.translation.z(), -m.speed, 1e-12);
  EXPECT_TRUE(in.left.has_pose && in.right.has_pose);
  EXPECT_EQ(in.left.frame, devices::PoseFrame::hand);
  // Opposite keys cancel; a long press stops at the reach.
  apply_keyboard(m, bit(Control::left_x_plus) | bit(Control::left_x_minus), {}, 1, in);
  EXPECT_NEAR(in.left.pose.translation.x(), m.speed, 1e-12);
  EXPECT_EQ(in.left.velocity, Vec3::Zero());
  apply_keyboard(m, bit(Control::left_x_plus), {}, 100, in);
  EXPECT_EQ(in.left.pose.translation.x(), m.reach);
  // No keys: the hands rest where they are.
  const Vec3 right = in.right.pose.translation;
  apply_keyboard(m, 0, {}, 1, in);
  EXPECT_EQ(in.right.pose.translation, right);
  EXPECT_EQ(in.right.velocity, Vec3::Zero());
}

TEST(KeyboardMapping, JawsIntegrateClutchAndPedalHold) {
  const KeyboardMapping m;
  devices::ConsoleInput in;
  apply_keyboard(m, bit(Control::left_jaw_close), {}, 0.25, in);
  EXPECT_NEAR(in.left.jaw, 0.25 * m.jaw_rate, 1e-12);
  EXPECT_TRUE(in.left.has_buttons);
  apply_keyboard(m, bit(Control::left_jaw_close), {}, 10, in);
  EXPECT_EQ(in.left.jaw, 1);  // closed, no further
  apply_keyboard(m, bit(Control::left_jaw_open) | bit(Control::right_clutch), {}, 0.1, in);
  EXPECT_NEAR(in.left.jaw, 1 - 0.1 * m.jaw_rate, 1e-12);
  EXPECT_FALSE(in.left.clutch);
  EXPECT_TRUE(in.right.clutch);
  EXPECT_EQ(in.right.jaw, 0);  // its keys were not touched
  apply_keyboard(m, bit(Control::pedal_coag), {}, 0.01, in);
  EXPECT_EQ(in.pedal, haptics::CauteryMode::coag);
  apply_keyboard(m, bit(Control::pedal_coag) | bit(Control::pedal_cut), {}, 0.01, in);
  EXPECT_EQ(in.pedal, haptics::CauteryMode::cut);  // cut wins, as on the gamepad
  apply_keyboard(m, 0, {}, 0.01, in);
  EXPECT_EQ(in.pedal, haptics::CauteryMode::off);
  EXPECT_FALSE(in.right.clutch);
}

TEST(KeyboardMapping, PowerStepsWithinTheGeneratorsRange) {
  const KeyboardMapping m;
  devices::ConsoleInput in;
  KeyboardEvents e;
  e.power_steps = 1;
  apply_keyboard(m, 0, e, 0.01, in);
  EXPECT_EQ(in.power_w, 45);
  e.power_steps = 10;
  apply_keyboard(m, 0, e, 0.01, in);
  EXPECT_EQ(in.power_w, m.power_max);
  e.power_steps = -100;
  apply_keyboard(m, 0, e, 0.01, in);
  EXPECT_EQ(in.power_w, m.power_min);
}

TEST(KeyboardMapping, DragsMoveAHandByTheirPixels) {
  const KeyboardMapping m;
  devices::ConsoleInput in;
  KeyboardEvents e;
  e.drag_px[1] = {100, 50, -20};  // right hand: right, down the screen (nearer), depth
  apply_keyboard(m, 0, e, 0.01, in);
  EXPECT_NEAR(in.right.pose.translation.x(), 100 * m.metres_per_pixel, 1e-12);
  EXPECT_NEAR(in.right.pose.translation.y(), -50 * m.metres_per_pixel, 1e-12);
  EXPECT_NEAR(in.right.pose.translation.z(), -20 * m.metres_per_pixel, 1e-12);
  EXPECT_NEAR(in.right.velocity.x(), 100 * m.metres_per_pixel / 0.01, 1e-9);
  EXPECT_EQ(in.left.pose.translation, Vec3::Zero());
  // Broken numbers are rest, not a jump.
  e.drag_px[1] = {NAN, INFINITY, 0};
  const Vec3 before = in.right.pose.translation;
  apply_keyboard(m, 0, e, NAN, in);
  EXPECT_EQ(in.right.pose.translation, before);
}

TEST(KeyboardMouseDevice, PollsTheKeysTheWindowHolds) {
  KeyboardMouseDevice d;
  devices::ConsoleInput in;
  d.poll(0, in);  // starts the clock
  EXPECT_TRUE(in.left.has_pose);
  d.set_held(Control::left_y_plus, true);
  d.set_held(Control::pedal_cut, true);
  d.poll(0.5, in);
  EXPECT_NEAR(in.left.pose.translation.y(), 0.05 * KeyboardMapping{}.speed, 1e-12)
      << "a gap between polls counts at most 50 ms";
  EXPECT_EQ(in.pedal, haptics::CauteryMode::cut);
  d.set_held(Control::left_y_plus, false);
  d.step_power(2);
  d.add_drag(devices::Hand::left, 10, 0, 0);
  d.poll(0.51, in);
  EXPECT_EQ(in.power_w, 50);
  EXPECT_NEAR(in.left.pose.translation.x(), 10 * KeyboardMapping{}.metres_per_pixel, 1e-9);
  d.poll(0.52, in);  // the drag was taken once
  EXPECT_NEAR(in.left.pose.translation.x(), 10 * KeyboardMapping{}.metres_per_pixel, 1e-9);
  d.release_all();
  d.poll(0.53, in);
  EXPECT_EQ(in.pedal, haptics::CauteryMode::off);
  d.reset();
  d.poll(0.54, in);
  EXPECT_EQ(in.left.pose.translation, Vec3::Zero());
  EXPECT_EQ(in.power_w, 40);
  EXPECT_TRUE(d.info().drives_left && d.info().drives_right && d.info().drives_pedal);
}

TEST(KeyboardMouseDevice, LeavesWhatAnotherDeviceDrivesAlone) {
  KeyboardMouseDevice d;
  d.set_drives(false, true, false);  // others drive the left hand and the pedal
  devices::ConsoleInput in;
  in.left.pose.translation = Vec3(0.01, 0.02, 0.03);  // as another device wrote them
  in.pedal = haptics::CauteryMode::coag;
  in.power_w = 35;
  d.set_held(Control::left_x_plus, true);
  d.set_held(Control::right_x_plus, true);
  d.set_held(Control::pedal_cut, true);
  d.poll(0, in);
  d.poll(0.01, in);
  EXPECT_EQ(in.left.pose.translation, Vec3(0.01, 0.02, 0.03));
  EXPECT_EQ(in.pedal, haptics::CauteryMode::coag);
  EXPECT_EQ(in.power_w, 35);
  EXPECT_GT(in.right.pose.translation.x(), 0);
  EXPECT_FALSE(d.info().drives_left);
  EXPECT_TRUE(d.info().drives_right);
  EXPECT_FALSE(d.info().drives_pedal);
}

TEST(KeyBindings, EveryControlHasOneKeyAndNoKeyTwoMeanings) {
  std::array<int, kControlCount> keys_of{};
  for (const KeyBinding& b : key_bindings()) {
    if (b.is_control) ++keys_of[std::size_t(b.control)];
    int same = 0;
    for (const KeyBinding& other : key_bindings())
      same += other.key == b.key ? 1 : 0;
    EXPECT_EQ(same, 1) << b.key_name;
    EXPECT_EQ(binding_for(b.key), &b);
  }
  for (int c = 0; c < kControlCount; ++c)
    EXPECT_EQ(keys_of[std::size_t(c)], 1) << "control " << c;
  ASSERT_NE(binding_for(256 /* GLFW_KEY_ESCAPE */), nullptr);
  EXPECT_EQ(binding_for(256)->command, Command::quit);
  EXPECT_NE(bindings_text().find("Escape"), std::string::npos);
}

}  // namespace
}  // namespace imasim::ui
