#pragma once
// What a surgeon's hands and feet give the simulator, whatever the device: a pose and velocity
// per hand (scene frame, SI), the clutch, the jaws, and the cautery pedal.
#include <cstdint>

#include "haptics/tissue_kind.hpp"
#include "math/pose.hpp"

namespace imasim::devices {

enum class Hand : std::uint8_t { left, right };

// What a pose is: the console hand (moved through the arm's motion scaling, clutch and remote
// centre of motion) or the instrument's hinge in the scene frame (a tracker on a tool).
enum class PoseFrame : std::uint8_t { hand, tool };

struct HandInput {
  Pose pose;  // (unit: m)
  PoseFrame frame = PoseFrame::hand;
  Vec3 velocity = Vec3::Zero();  // (unit: m/s)
  double time_s = 0;             // the device's time stamp of the pose (unit: s)
  bool has_pose = false;         // false until the first pose arrives
  bool has_buttons = false;      // false until the first clutch and jaw values arrive
  bool clutch = false;           // true = engaged (the hand moves without the instrument)
  Real jaw = 0;                  // 0 open .. 1 closed
  // Its device is gone: the console holds it (clutch engaged, still) until the device is back
  // (console/loss_guard.hpp). Set by the console, never by a device.
  bool lost = false;
};

struct ConsoleInput {
  HandInput left, right;
  haptics::CauteryMode pedal = haptics::CauteryMode::off;
  Real power_w = 40;        // the generator's setting (unit: W)
  bool pedal_lost = false;  // the pedal's device is gone: off until it is back (set by the console)

  HandInput& hand(Hand h) { return h == Hand::left ? left : right; }
};

}  // namespace imasim::devices
