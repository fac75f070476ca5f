// What a lost device leaves behind (console/loss_guard.hpp): tick by
// tick, a device that vanishes mid-cut releases its parts at the tick its loss is seen, and a
// device that comes back drives them again only once it is read afresh.
#include <gtest/gtest.h>

#include "console/loss_guard.hpp"

namespace imasim::console {
namespace {

using devices::ConsoleInput;
using devices::Hand;
using haptics::CauteryMode;

// A hand device cutting at 300 W with both hands posed, the clutch released.
ConsoleInput cutting() {
  ConsoleInput in;
  for (int h = 0; h < 2; ++h) {
    devices::HandInput& hand = in.hand(Hand(h));
    hand.has_pose = hand.has_buttons = true;
    hand.pose.translation = Vec3(0.01 * (h + 1), 0.02, 0.03);
    hand.velocity = Vec3(0.1, 0, 0);
    hand.jaw = Real(0.7);
  }
  in.pedal = CauteryMode::cut;
  in.power_w = 300;
  return in;
}

TEST(LossGuard, AHandDeviceVanishingMidCutReleasesBothHandsAndThePedalAtOnce) {
  LossGuard guard({{true, true, true}});  // one device drives everything
  ConsoleInput raw = cutting(), out;
  std::vector<bool> up = {true};
  for (int k = 0; k < 5; ++k)
    guard.apply(k * 1e-3, up, std::uint64_t(k), raw, out);
  EXPECT_EQ(out.pedal, CauteryMode::cut);  // nothing lost yet: what the device said
  EXPECT_EQ(out.power_w, 300);
  EXPECT_FALSE(out.left.lost || out.right.lost || out.pedal_lost);
  const Vec3 before = out.right.pose.translation;

  // Gone at 5 ms, its last claims still in `raw` (a closed socket changes nothing by itself).
  up[0] = false;
  guard.apply(5e-3, up, 5, raw, out);
  EXPECT_EQ(out.pedal, CauteryMode::off);
  EXPECT_EQ(out.power_w, 0);
  EXPECT_TRUE(out.pedal_lost);
  for (int h = 0; h < 2; ++h) {
    const devices::HandInput& hand = out.hand(Hand(h));
    EXPECT_TRUE(hand.lost);
    EXPECT_TRUE(hand.clutch);  // the instrument holds still
    EXPECT_EQ(hand.velocity, Vec3::Zero());
    EXPECT_TRUE(hand.has_pose);
    EXPECT_EQ(hand.jaw, Real(0.7));  // what it holds stays held
    // The device's own claims are void, to be read afresh when it returns.
    EXPECT_FALSE(raw.hand(Hand(h)).has_pose);
    EXPECT_FALSE(raw.hand(Hand(h)).has_buttons);
  }
  EXPECT_EQ(out.right.pose.translation, before);
  EXPECT_EQ(raw.pedal, CauteryMode::off);
  for (int k = 6; k < 56; ++k)
    guard.apply(k * 1e-3, up, std::uint64_t(k / 5), raw, out);
  EXPECT_EQ(out.pedal, CauteryMode::off);
  EXPECT_TRUE(out.right.lost);
  for (std::size_t p = 0; p < kParts; ++p) {
    EXPECT_EQ(guard.parts()[p].losses, 1u);
    EXPECT_TRUE(guard.parts()[p].held);
    EXPECT_NEAR(guard.parts()[p].lost_s, 0.050, 1e-9);
  }
}

TEST(LossGuard, AReturnedDeviceDrivesAgainOnlyWithANewPoseAfterThePhysicsSawTheHold) {
  LossGuard guard({{true, true, true}});
  ConsoleInput raw = cutting(), out;
  std::vector<bool> up = {true};
  guard.apply(0, up, 10, raw, out);
  up[0] = false;
  guard.apply(1e-3, up, 10, raw, out);
  ASSERT_TRUE(out.left.lost);
  // Back, but nothing sent yet: still held.
  up[0] = true;
  guard.apply(2e-3, up, 11, raw, out);
  EXPECT_TRUE(out.left.lost && out.right.lost);
  // A new pose arrives, but the physics has stepped once only since the loss.
  raw.left.has_pose = raw.right.has_pose = true;
  raw.left.pose.translation = Vec3(0.2, 0, 0);
  std::array<bool, 2> ended = guard.apply(3e-3, up, 11, raw, out);
  EXPECT_FALSE(ended[0] || ended[1]);
  EXPECT_TRUE(out.left.clutch);
  EXPECT_NE(out.left.pose.translation, raw.left.pose.translation);
  // Two steps held: the hands follow the new poses (the clutch is the device's own again).
  ended = guard.apply(4e-3, up, 12, raw, out);
  EXPECT_TRUE(ended[0] && ended[1]);
  EXPECT_FALSE(out.left.lost || out.right.lost || out.pedal_lost);
  EXPECT_FALSE(out.left.clutch);
  EXPECT_EQ(out.left.pose.translation, Vec3(0.2, 0, 0));
  // The pedal stays off until the foot presses it again; the generator's setting is back.
  EXPECT_EQ(out.pedal, CauteryMode::off);
  EXPECT_EQ(out.power_w, 300);
  raw.pedal = CauteryMode::coag;
  guard.apply(5e-3, up, 12, raw, out);
  EXPECT_EQ(out.pedal, CauteryMode::coag);
}

TEST(LossGuard, AVanishedPedalBoxStopsTheEnergyAndLeavesTheHandsAlone) {
  // Device 0 the hands, device 1 a foot switch.
  LossGuard guard({{true, true, false}, {false, false, true}});
  ConsoleInput raw = cutting(), out;
  std::vector<bool> up = {true, true};
  guard.apply(0, up, 1, raw, out);
  up[1] = false;
  guard.apply(1e-3, up, 1, raw, out);
  EXPECT_EQ(out.pedal, CauteryMode::off);
  EXPECT_EQ(out.power_w, 0);
  EXPECT_TRUE(out.pedal_lost);
  EXPECT_FALSE(out.left.lost || out.right.lost);
  EXPECT_FALSE(out.right.clutch);
  EXPECT_EQ(out.right.velocity, Vec3(0.1, 0, 0));
  EXPECT_EQ(guard.parts()[std::size_t(Part::pedal)].losses, 1u);
  EXPECT_EQ(guard.parts()[std::size_t(Part::left)].losses, 0u);
  // Plugged in again: no pose to wait for; the foot must press anew.
  up[1] = true;
  guard.apply(2e-3, up, 4, raw, out);
  EXPECT_FALSE(out.pedal_lost);
  EXPECT_EQ(out.pedal, CauteryMode::off);
  EXPECT_EQ(out.power_w, 300);
}

TEST(LossGuard, ADeviceNeverConnectedIsNotLost) {
  // A server waiting for its first peer, and a foot switch never plugged in.
  LossGuard guard({{true, true, false}, {false, false, true}});
  ConsoleInput raw, out;
  const std::vector<bool> down = {false, false};
  for (int k = 0; k < 10; ++k)
    guard.apply(k * 1e-3, down, 0, raw, out);
  EXPECT_FALSE(out.left.lost || out.right.lost || out.pedal_lost);
  EXPECT_EQ(out.power_w, raw.power_w);
  for (const PartLoss& p : guard.parts())
    EXPECT_EQ(p.losses, 0u);
}

TEST(LossGuard, ALostHandStopsTheCauteryEvenWithThePedalBoxStillThere) {
  LossGuard guard({{true, false, false}, {false, true, false}, {false, false, true}});
  ConsoleInput raw = cutting(), out;
  std::vector<bool> up = {true, true, true};
  guard.apply(0, up, 1, raw, out);
  up[0] = false;  // the forceps' hand
  guard.apply(1e-3, up, 1, raw, out);
  EXPECT_TRUE(out.left.lost);
  EXPECT_FALSE(out.right.lost || out.pedal_lost);
  EXPECT_EQ(out.pedal, CauteryMode::off);
  EXPECT_EQ(out.power_w, 0);
}

}  // namespace
}  // namespace imasim::console
