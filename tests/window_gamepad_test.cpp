// The window's input with a game controller (`imasim window --devices gamepad`): the keyboard
// first and the pad after it in the live console, the keys driving only what the pad does not
// (as window_command sets them up). A virtual SDL controller (no hardware, no display) moves the
// forceps' hand and presses the cut pedal; the session's next input carries both, and the keys
// no longer move the hands the pad owns.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "devices/gamepad_device.hpp"
#include "runner/input_source.hpp"
#include "scene/thorax_scene.hpp"
#include "ui/keyboard_mouse_device.hpp"
#include "virtual_joystick.hpp"

namespace imasim::ui {
namespace {

using namespace std::chrono_literals;

TEST(WindowGamepad, TheControllerDrivesBothHandsAndThePedalThroughTheLiveConsole) {
  test::VirtualJoystick pad("imasim window test pad", true);
  ASSERT_TRUE(pad.attached()) << SDL_GetError();
  session::SurgicalSession s =
      session::make_surgical_session(scene::default_thorax_scene_params(), {});
  std::vector<std::unique_ptr<devices::InputDevice>> list;
  auto owned_keyboard = std::make_unique<KeyboardMouseDevice>();
  KeyboardMouseDevice* keyboard = owned_keyboard.get();
  list.push_back(std::move(owned_keyboard));
  auto gamepad = std::make_unique<devices::GamepadDevice>();
  ASSERT_TRUE(gamepad->connected());
  const devices::DeviceInfo info = gamepad->info();
  EXPECT_TRUE(info.drives_left && info.drives_right && info.drives_pedal);
  keyboard->set_drives(!info.drives_left, !info.drives_right, !info.drives_pedal);
  list.push_back(std::move(gamepad));
  console::LiveConsoleParams params;
  params.loop.realtime_priority = 0;
  runner::ConsoleInputSource source(std::move(list), params, [keyboard] { keyboard->reset(); });

  // The left stick right, the cut button (A), and the right-hand key held on the keyboard.
  pad.set_axis(SDL_CONTROLLER_AXIS_LEFTX, 32767);
  pad.set_button(SDL_CONTROLLER_BUTTON_A, true);
  keyboard->set_held(Control::right_x_plus, true);
  session::SessionInput in;
  const auto until = std::chrono::steady_clock::now() + 10s;
  do {
    in = source.next(s);
    std::this_thread::sleep_for(2ms);
  } while (in.left.pose.translation.x() <= 0.003 && std::chrono::steady_clock::now() < until);
  EXPECT_GT(in.left.pose.translation.x(), 0.003) << "the stick moved the left hand";
  EXPECT_EQ(in.left.source, surgery::PoseSource::hand);
  EXPECT_EQ(in.right.pedal, surgery::PedalMode::cut) << "the pad's A button is the cut pedal";
  EXPECT_LT(std::abs(in.right.pose.translation.x()), 1e-9)
      << "the pad owns the right hand: the key does not move it";
  keyboard->set_held(Control::right_x_plus, false);
  source.stop();
}

}  // namespace
}  // namespace imasim::ui
