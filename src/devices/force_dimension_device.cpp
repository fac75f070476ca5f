#include "devices/force_dimension_device.hpp"

#include <dhdc.h>

#include <algorithm>
#include <stdexcept>

namespace imasim::devices {

namespace {

// The jaws' range on a gripper: open at this angle or more (unit: rad).
constexpr double kGripperOpenRad = 0.5;

}  // namespace

ForceDimensionDevice::ForceDimensionDevice(int index, Hand hand) : hand_(hand) {
  id_ = dhdOpenID(static_cast<char>(index));
  if (id_ < 0)
    throw std::runtime_error("Force Dimension: cannot open device " + std::to_string(index) + ": " +
                             dhdErrorGetLastStr());
  const char* name = dhdGetSystemName(static_cast<char>(id_));
  name_ = name != nullptr ? name : "Force Dimension device";
  gripper_ = dhdHasGripper(static_cast<char>(id_));
  dhdEnableForce(DHD_ON, static_cast<char>(id_));
  ok_ = true;
}

ForceDimensionDevice::~ForceDimensionDevice() {
  if (id_ >= 0) {
    dhdSetForce(0, 0, 0, static_cast<char>(id_));
    dhdClose(static_cast<char>(id_));
  }
}

void ForceDimensionDevice::poll(double now_s, ConsoleInput& input) {
  const char id = static_cast<char>(id_);
  double x = 0, y = 0, z = 0, r[3][3] = {};
  if (dhdGetPosition(&x, &y, &z, id) < DHD_NO_ERROR) {
    ok_ = false;
    return;
  }
  dhdGetOrientationFrame(r, id);  // identity on devices without a wrist
  ok_ = true;
  HandInput& h = input.hand(hand_);
  const Vec3 p(x, y, z);
  if (h.has_pose && now_s > h.time_s)
    h.velocity = (p - h.pose.translation) / Real(now_s - h.time_s);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      h.pose.rotation(i, j) = Real(r[i][j]);
  h.pose.translation = p;
  h.frame = PoseFrame::hand;
  h.time_s = now_s;
  h.has_pose = h.has_buttons = true;
  double angle = kGripperOpenRad;
  if (gripper_ && dhdGetGripperAngleRad(&angle, id) >= DHD_NO_ERROR)
    h.jaw = Real(1 - std::min(1.0, std::max(0.0, angle / kGripperOpenRad)));
  else
    h.jaw = dhdGetButton(0, id) ? 1 : 0;
  h.clutch = dhdGetButton(1, id) != 0;
}

void ForceDimensionDevice::send_force(Hand hand, const Vec3& f, double) {
  if (hand != hand_ || !f.allFinite()) return;
  if (dhdSetForce(f.x(), f.y(), f.z(), static_cast<char>(id_)) < DHD_NO_ERROR) ok_ = false;
}

DeviceInfo ForceDimensionDevice::info() const {
  DeviceInfo d;
  d.kind = "force_dimension";
  d.name = name_;
  d.mapping = std::string(hand_ == Hand::left ? "left" : "right") +
              " hand: end effector pose (m, the device's frame); " +
              (gripper_ ? "gripper -> jaw" : "button 0 -> jaw (held = closed)") +
              ", button 1 -> clutch; force out";
  d.connected = ok_;
  d.force_feedback = true;
  d.max_force_n = 12;  // the smallest of the family's continuous forces (omega.3)
  d.drives_left = hand_ == Hand::left;
  d.drives_right = hand_ == Hand::right;
  return d;
}

}  // namespace imasim::devices
