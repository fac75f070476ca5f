// Devices that vanish mid-cut, through the live console's 1 kHz loop:
// the hand's force is zero from the tick the loss is seen, the pedal goes off and the power to 0,
// the clutch engages so the instrument holds still; a device that comes back (its clock
// restarted) is followed again. Each kind of device: an OpenIGTLink client that closes, one of
// several OpenIGTLink peers (a pedal box beside a tracker) that closes, a game controller and a
// foot switch pulled out (SDL virtual joysticks).
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "console/live_console.hpp"
#include "devices/emulated_console.hpp"
#include "devices/gamepad_device.hpp"
#include "devices/igtl_device.hpp"
#include "devices/joystick_pedal_device.hpp"
#include "loopback_client.hpp"
#include "virtual_joystick.hpp"

namespace imasim::console {
namespace {

using devices::ConsoleInput;
using haptics::CauteryMode;

LiveConsoleParams test_params() {
  LiveConsoleParams p;
  p.loop.realtime_priority = 0;  // a test need not ask for it
  p.safety.ramp_s = 0.01;        // full force soon after the start
  return p;
}

// A model pressing the chest wall's plane 2 mm above the hand's origin (normal +z): 2 N of eq. 17.
std::array<haptics::LocalModel, 2> pressing(double now_s, std::uint64_t step) {
  std::array<haptics::LocalModel, 2> m;
  for (haptics::LocalModel& model : m) {
    model.time_s = now_s;
    model.step = step;
    model.contact_count = 1;
    model.contacts[0].point = Vec3(0, 0, 0.002);
    model.contacts[0].normal = Vec3::UnitZ();
    model.contacts[0].tissue = haptics::TissueKind::chest_wall;
  }
  return m;
}

// Plays the physics' side for `seconds`: a model every 5 ms, `each_ms` called every millisecond.
template <class Each>
void run_for(LiveConsole& console, double seconds, std::uint64_t& step, Each each_ms) {
  const auto start = std::chrono::steady_clock::now();
  for (int ms = 0; ms < int(seconds * 1000); ++ms) {
    std::this_thread::sleep_until(start + std::chrono::milliseconds(ms));
    if (ms % 5 == 0) console.publish_models(pressing(console.now_s(), ++step));
    each_ms(ms);
  }
}

// Polls the console's latest input until `done` holds (5 s at most); whether it did.
template <class Done>
bool wait_for(LiveConsole& console, std::uint64_t& step, Done done) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(5);
  while (std::chrono::steady_clock::now() < end) {
    if (done(console.latest_input())) return true;
    console.publish_models(pressing(console.now_s(), ++step));
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return false;
}

// A desktop haptic device on both hands and the pedal, pressing 2 mm into the plane while it
// cuts at 300 W, that vanishes at the first tick at or after `vanish_s`; it records the forces
// it is sent, before and after (a real device would no longer hear the second kind).
class VanishingDevice final : public devices::InputDevice {
 public:
  explicit VanishingDevice(double vanish_s) : vanish_s_(vanish_s) {}
  void poll(double now_s, ConsoleInput& input) override {
    if (now_s >= vanish_s_ && !gone_) {
      gone_ = true;
      gone_at_s_ = now_s;
    }
    if (gone_) return;
    for (int h = 0; h < 2; ++h) {
      devices::HandInput& hand = input.hand(devices::Hand(h));
      hand.pose.translation = Vec3::Zero();
      hand.time_s = now_s;
      hand.has_pose = hand.has_buttons = true;
    }
    input.pedal = CauteryMode::cut;
    input.power_w = 300;
  }
  void send_force(devices::Hand, const Vec3& force_n, double now_s) override {
    if (!gone_) {
      if (now_s > vanish_s_ - 0.05) largest_before_ = std::max(largest_before_, force_n.norm());
      return;
    }
    ++sent_after_;
    largest_after_ = std::max(largest_after_, force_n.norm());
  }
  bool connected() const override { return !gone_; }
  devices::DeviceInfo info() const override {
    devices::DeviceInfo d;
    d.kind = "test";
    d.connected = !gone_;
    d.force_feedback = true;
    d.drives_left = d.drives_right = d.drives_pedal = true;
    return d;
  }
  // Read after the console stopped (its loop thread joined).
  double gone_at_s_ = -1;
  Real largest_before_ = 0, largest_after_ = 0;
  std::uint64_t sent_after_ = 0;

 private:
  double vanish_s_;
  bool gone_ = false;
};

TEST(DeviceLoss, TheForceIsZeroFromTheVeryTickADeviceVanishes) {
  auto owned = std::make_unique<VanishingDevice>(0.3);
  VanishingDevice* device = owned.get();
  std::vector<std::unique_ptr<devices::InputDevice>> list;
  list.push_back(std::move(owned));
  LiveConsole console(std::move(list), test_params());
  console.start();
  std::uint64_t step = 0;
  ConsoleInput before;
  run_for(console, 0.25, step, [&](int) { before = console.latest_input(); });
  EXPECT_EQ(before.pedal, CauteryMode::cut);
  EXPECT_EQ(before.power_w, 300);
  run_for(console, 0.15, step, [](int) {});
  const ConsoleInput after = console.latest_input();
  console.stop();

  // Pressing 2 mm: eq. 17's 2 N on each hand before; from the loss's own tick, nothing.
  EXPECT_GT(device->largest_before_, Real(0.5));
  ASSERT_GT(device->gone_at_s_, 0.0);
  EXPECT_GT(device->sent_after_, 50u);  // two hands a tick for about 0.1 s
  EXPECT_EQ(device->largest_after_, 0);
  EXPECT_EQ(after.pedal, CauteryMode::off);
  EXPECT_EQ(after.power_w, 0);
  EXPECT_TRUE(after.left.lost && after.right.lost && after.pedal_lost);
  EXPECT_TRUE(after.left.clutch && after.right.clutch);
  const LiveConsoleStats stats = console.stats();
  for (const PartLoss& p : stats.losses) {
    EXPECT_EQ(p.losses, 1u);
    EXPECT_TRUE(p.held);
    EXPECT_GT(p.lost_s, 0.05);
  }
  EXPECT_GT(stats.safety[0].device_lost, 50u);
}

TEST(DeviceLoss, AnOpenIgtlinkClientClosingMidCutIsReleasedAndAReturningOneFollowed) {
  devices::IgtlDeviceConfig config;
  config.link.port = 0;
  auto igtl = std::make_unique<devices::IgtlDevice>(config);
  const devices::IgtlDevice* link = igtl.get();
  const std::uint16_t port = igtl->link().port();
  std::vector<std::unique_ptr<devices::InputDevice>> list;
  list.push_back(std::move(igtl));
  LiveConsole console(std::move(list), test_params());
  console.start();
  std::uint64_t step = 0;

  // A console cutting at 300 W with both hands posed, whose clock has run for an hour.
  devices::EmulatorTarget cutting;
  cutting.has_pose = {true, true};
  cutting.pose[1].translation = Vec3(0.05, 0, 0);
  cutting.pedal = CauteryMode::cut;
  cutting.power_w = 300;
  {
    devices::EmulatedConsole first("127.0.0.1", port, 5.0);
    run_for(console, 0.2, step,
            [&](int ms) { ASSERT_TRUE(first.tick(3600.0 + ms * 1e-3, cutting)); });
    const ConsoleInput on = console.latest_input();
    EXPECT_EQ(on.pedal, CauteryMode::cut);
    EXPECT_EQ(on.power_w, 300);
  }  // closes its connection without lifting the pedal
  ASSERT_TRUE(wait_for(console, step, [](const ConsoleInput& in) { return in.pedal_lost; }));
  const ConsoleInput lost = console.latest_input();
  EXPECT_EQ(lost.pedal, CauteryMode::off);
  EXPECT_EQ(lost.power_w, 0);
  EXPECT_TRUE(lost.left.lost && lost.right.lost);
  EXPECT_TRUE(lost.left.clutch && lost.right.clutch);
  EXPECT_NEAR(lost.right.pose.translation.x(), 0.05, 1e-3);  // held where it was

  // Another device with its clock restarted (stamps an hour earlier): followed, not refused.
  devices::EmulatorTarget resting;
  resting.has_pose = {true, true};
  resting.pose[1].translation = Vec3(-0.03, 0.01, 0);
  devices::EmulatedConsole second("127.0.0.1", port, 5.0);
  double t = 1.0;
  ASSERT_TRUE(wait_for(console, step, [&](const ConsoleInput& in) {
    second.tick(t += 1e-3, resting);
    return !in.left.lost && !in.right.lost && !in.pedal_lost;
  }));
  const ConsoleInput back = console.latest_input();
  EXPECT_NEAR(back.right.pose.translation.x(), -0.03, 2e-3);
  EXPECT_FALSE(back.right.clutch);
  EXPECT_EQ(back.pedal, CauteryMode::off);  // the new device never pressed it
  console.stop();
  EXPECT_EQ(link->link().counters().refused[std::size_t(devices::IgtlRefusal::out_of_order)], 0u);
  const LiveConsoleStats stats = console.stats();
  EXPECT_EQ(stats.losses[0].losses, 1u);
  EXPECT_FALSE(stats.losses[0].held);
}

TEST(DeviceLoss, AGameControllerPulledOutMidCutIsReleased) {
  test::VirtualJoystick stick("imasim test pad", true);
  ASSERT_TRUE(stick.attached()) << SDL_GetError();
  std::vector<std::unique_ptr<devices::InputDevice>> list;
  list.push_back(std::make_unique<devices::GamepadDevice>());
  LiveConsole console(std::move(list), test_params());
  stick.set_axis(SDL_CONTROLLER_AXIS_LEFTX, 32767);  // the left hand moving
  stick.set_button(SDL_CONTROLLER_BUTTON_A, true);   // cut
  console.start();
  std::uint64_t step = 0;
  ASSERT_TRUE(wait_for(console, step, [](const ConsoleInput& in) {
    return in.pedal == CauteryMode::cut && in.left.velocity.x() > 0;
  }));
  stick.unplug();
  ASSERT_TRUE(wait_for(console, step, [](const ConsoleInput& in) { return in.left.lost; }));
  const ConsoleInput lost = console.latest_input();
  EXPECT_EQ(lost.pedal, CauteryMode::off);
  EXPECT_EQ(lost.power_w, 0);
  EXPECT_TRUE(lost.right.lost && lost.pedal_lost);
  EXPECT_TRUE(lost.left.clutch && lost.right.clutch);
  EXPECT_EQ(lost.left.velocity, Vec3::Zero());
  console.stop();
  EXPECT_EQ(console.stats().losses[0].losses, 1u);
}

TEST(DeviceLoss, AFootSwitchPulledOutMidCutStopsTheEnergyOnly) {
  test::VirtualJoystick stick("imasim test foot switch", false, 3);
  ASSERT_TRUE(stick.attached()) << SDL_GetError();
  devices::PedalMapping mapping;
  mapping.joystick = "foot switch";
  std::vector<std::unique_ptr<devices::InputDevice>> list;
  list.push_back(std::make_unique<devices::JoystickPedalDevice>(mapping));
  LiveConsole console(std::move(list), test_params());
  stick.set_button(int(mapping.cut_button), true);
  console.start();
  std::uint64_t step = 0;
  ASSERT_TRUE(
      wait_for(console, step, [](const ConsoleInput& in) { return in.pedal == CauteryMode::cut; }));
  stick.unplug();
  ASSERT_TRUE(wait_for(console, step, [](const ConsoleInput& in) { return in.pedal_lost; }));
  const ConsoleInput lost = console.latest_input();
  EXPECT_EQ(lost.pedal, CauteryMode::off);
  EXPECT_EQ(lost.power_w, 0);
  EXPECT_FALSE(lost.left.lost || lost.right.lost);  // the hands are another device's
  console.stop();
  EXPECT_EQ(console.stats().losses[2].losses, 1u);
  EXPECT_EQ(console.stats().losses[0].losses, 0u);
}

using IgtlPeer = test::LoopbackClient;

// A tracker on both hands and a pedal box, two peers of one OpenIGTLink server: the pedal box
// vanishing mid-cut stops the energy at once, while the tracker's hands stay followed and felt.
TEST(DeviceLoss, APedalBoxPeerVanishingMidCutStopsTheEnergyAndLeavesTheTrackersHands) {
  devices::IgtlDeviceConfig config;
  config.link.port = 0;
  auto igtl = std::make_unique<devices::IgtlDevice>(config);
  const std::uint16_t port = igtl->link().port();
  std::vector<std::unique_ptr<devices::InputDevice>> list;
  list.push_back(std::move(igtl));
  LiveConsole console(std::move(list), test_params());
  console.start();
  std::uint64_t step = 0;
  IgtlPeer tracker(port), pedal_box(port);
  double t = 10.0;
  auto track = [&] {
    t += 1e-3;
    tracker.send(devices::encode_pose("LeftHand", Pose{}, t));
    tracker.send(devices::encode_pose("RightHand", Pose{}, t));
  };
  pedal_box.send(devices::encode_values("Pedal", {1, 300}, 0.0));
  pedal_box.send(devices::encode_values("Footswitch", {1}, 0.0));  // a name the scene lacks
  ASSERT_TRUE(wait_for(console, step, [&](const ConsoleInput& in) {
    track();
    return in.pedal == CauteryMode::cut && in.right.has_pose;
  }));
  pedal_box.close();
  ASSERT_TRUE(wait_for(console, step, [&](const ConsoleInput& in) {
    track();
    return in.pedal_lost;
  }));
  const ConsoleInput lost = console.latest_input();
  EXPECT_EQ(lost.pedal, CauteryMode::off);
  EXPECT_EQ(lost.power_w, 0);
  EXPECT_FALSE(lost.left.lost || lost.right.lost);  // the tracker is still there
  EXPECT_FALSE(lost.right.clutch);
  run_for(console, 0.1, step, [&](int) { track(); });
  const ConsoleInput later = console.latest_input();
  // What the window's panel shows: the peers, the refusal by reason and name, the pedal's loss.
  const DeviceTally tally = console.device_tally();
  EXPECT_GT(tally.time_s, 0);
  EXPECT_EQ(tally.counts.peers_seen, 2u);
  EXPECT_EQ(tally.counts.peers_dropped, 1u);
  EXPECT_EQ(tally.counts.peers_connected, 1u);
  EXPECT_EQ(tally.counts.refused_by_reason[std::size_t(devices::IgtlRefusal::unknown_device)], 1u);
  ASSERT_EQ(tally.counts.named, 1u);
  EXPECT_STREQ(tally.counts.refused_names[0].name.data(), "Footswitch");
  EXPECT_EQ(tally.losses[2].losses, 1u);
  EXPECT_TRUE(tally.losses[2].held);
  EXPECT_GT(tally.losses[2].lost_s, 0.05);
  EXPECT_EQ(tally.losses[0].losses, 0u);
  console.stop();
  EXPECT_EQ(later.pedal, CauteryMode::off);
  EXPECT_FALSE(later.left.lost || later.right.lost);
  EXPECT_EQ(console.stats().losses[2].losses, 1u);
  EXPECT_EQ(console.stats().losses[0].losses, 0u);
  EXPECT_EQ(console.stats().losses[1].losses, 0u);
}

}  // namespace
}  // namespace imasim::console
