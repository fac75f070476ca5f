// The console end to end over loopback (console/live_console.hpp, devices/emulated_console.hpp):
// two emulated haptic devices call imasim's OpenIGTLink server, the 1 kHz loop renders the
// local model against the hand they send, and the force they receive is eq. 17's for the
// hand's actual depth; when the devices go away the force is zero and the loss counted.
#include <gtest/gtest.h>

#include <chrono>
#include <thread>

#include "console/live_console.hpp"
#include "devices/emulated_console.hpp"
#include "devices/igtl_device.hpp"

namespace imasim::console {
namespace {

TEST(LiveConsole, EmulatedDevicesOverLoopbackReceiveTheForceLaw) {
  devices::IgtlDeviceConfig config;
  config.link.port = 0;
  auto device = std::make_unique<devices::IgtlDevice>(config);
  const std::uint16_t port = device->link().port();
  std::vector<std::unique_ptr<devices::InputDevice>> list;
  list.push_back(std::move(device));
  LiveConsoleParams params;
  params.loop.realtime_priority = 0;  // a test need not ask for it
  LiveConsole console(std::move(list), params);
  console.start();
  auto emulator = std::make_unique<devices::EmulatedConsole>("127.0.0.1", port, 5.0);

  // The left hand is steered to the origin; a fascia plane 2 mm above it (normal +z) pushes it
  // back: it settles where its grip spring (200 N/m) balances k_d d, at d = 2 mm k_s/(k_s + k_d).
  devices::EmulatorTarget target;
  target.has_pose = {true, true};
  target.pose[1].translation = Vec3(0.05, 0, 0);
  haptics::LocalModel touching;
  touching.contact_count = 1;
  touching.contacts[0].point = Vec3(0, 0, 0.002);
  touching.contacts[0].normal = Vec3::UnitZ();
  touching.contacts[0].tissue = haptics::TissueKind::fascia;
  const auto start = std::chrono::steady_clock::now();
  for (int ms = 0; ms < 1500; ++ms) {
    std::this_thread::sleep_until(start + std::chrono::milliseconds(ms));
    if (ms % 5 == 0) {
      touching.time_s = console.now_s();
      touching.step = std::uint64_t(ms / 5 + 1);
      haptics::LocalModel free_hand;
      free_hand.time_s = touching.time_s;
      free_hand.step = touching.step;
      console.publish_models({touching, free_hand});
    }
    ASSERT_TRUE(emulator->tick(1.0 + ms * 1e-3, target));
  }
  const haptics::ContactForceParams fascia =
      haptics::default_force_model_params().of(haptics::TissueKind::fascia);
  const Real grip = devices::EmulatedHandParams{}.stiffness;
  const Vec3 hand = emulator->hands()[0].x;
  const Vec3 force = emulator->force()[0];
  // The force received is eq. 17 at the hand's depth (at rest: no damping term) ...
  EXPECT_NEAR(force.z(), fascia.stiffness * (0.002 - hand.z()), 0.02 * force.z());
  EXPECT_NEAR(force.x(), 0, 1e-6);
  // ... and the hand rests where the closed form puts it.
  const Real expected = fascia.stiffness * grip * Real(0.002) / (fascia.stiffness + grip);
  EXPECT_NEAR(force.z(), expected, 0.03 * expected);
  EXPECT_EQ(emulator->force()[1], Vec3::Zero());  // nothing touches the right hand
  EXPECT_GT(emulator->forces_received(), 2000u);

  // The devices go away: the loop notices and commands zero at once.
  emulator.reset();
  std::this_thread::sleep_for(std::chrono::milliseconds(100));
  console.stop();
  const LiveConsoleStats stats = console.stats();
  EXPECT_GT(stats.safety[0].device_lost, 10u);
  EXPECT_GT(stats.loop.ticks, 1400u);
  EXPECT_LE(stats.force_max_n, params.safety.device_max_force);
  EXPECT_EQ(stats.safety[0].non_finite, 0u);
}

}  // namespace
}  // namespace imasim::console
