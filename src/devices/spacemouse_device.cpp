#include "devices/spacemouse_device.hpp"

#include <spnav.h>

#include <algorithm>
#include <cmath>

#include "math/pose.hpp"

namespace imasim::devices {

namespace {

Real shaped(int raw, const SpaceMouseMapping& m) {
  const Real a = std::clamp(Real(raw) / m.full_scale, Real(-1), Real(1));
  const Real magnitude = std::abs(a);
  if (magnitude <= m.dead_zone) return 0;
  return std::copysign((magnitude - m.dead_zone) / (1 - m.dead_zone), a);
}

}  // namespace

void apply_space_motion(const SpaceMouseMapping& m, const std::array<int, 6>& motion, Real dt,
                        HandInput& hand) {
  const Vec3 push(shaped(motion[0], m), shaped(motion[1], m), shaped(motion[2], m));
  const Vec3 twist(shaped(motion[3], m), shaped(motion[4], m), shaped(motion[5], m));
  hand.frame = PoseFrame::hand;
  hand.velocity = m.speed * push;
  hand.pose.translation += dt * hand.velocity;
  const Real angle = m.turn_rate * dt * twist.norm();
  if (angle > 0) hand.pose.rotation = axis_angle(twist.normalized(), angle) * hand.pose.rotation;
  hand.has_pose = true;
}

SpaceMouseDevice::SpaceMouseDevice(const SpaceMouseMapping& mapping) : mapping_(mapping) {}

SpaceMouseDevice::~SpaceMouseDevice() {
  if (open_) spnav_close();
}

void SpaceMouseDevice::poll(double now_s, ConsoleInput& input) {
  if (!open_ && now_s - last_try_s_ >= 1.0) {
    last_try_s_ = now_s;
    open_ = spnav_open() != -1;
  }
  if (!open_) return;
  spnav_event ev;
  while (spnav_poll_event(&ev) != 0) {
    if (ev.type == SPNAV_EVENT_MOTION) {
      motion_ = {ev.motion.x, ev.motion.y, ev.motion.z, ev.motion.rx, ev.motion.ry, ev.motion.rz};
    } else if (ev.type == SPNAV_EVENT_BUTTON && ev.button.bnum >= 0 && ev.button.bnum < 2) {
      held_[std::size_t(ev.button.bnum)] = ev.button.press != 0;
    }
  }
  HandInput& hand = input.hand(mapping_.hand);
  const Real dt = last_poll_s_ < 0 ? Real(0) : Real(std::clamp(now_s - last_poll_s_, 0.0, 0.05));
  last_poll_s_ = now_s;
  apply_space_motion(mapping_, motion_, dt, hand);
  hand.has_buttons = true;
  hand.jaw = held_[std::size_t(mapping_.jaw_button & 1)] ? 1 : 0;
  hand.clutch = held_[std::size_t(mapping_.clutch_button & 1)];
}

DeviceInfo SpaceMouseDevice::info() const {
  DeviceInfo d;
  d.kind = "spacemouse";
  d.name = open_ ? "3D mouse (spacenavd)" : "no spacenavd running";
  d.mapping = std::string(mapping_.hand == Hand::left ? "left" : "right") +
              " hand: cap push -> velocity, twist -> rotation; button " +
              std::to_string(mapping_.jaw_button) + " -> jaw (held = closed), button " +
              std::to_string(mapping_.clutch_button) + " -> clutch";
  d.connected = open_;
  d.drives_left = mapping_.hand == Hand::left;
  d.drives_right = mapping_.hand == Hand::right;
  return d;
}

}  // namespace imasim::devices
