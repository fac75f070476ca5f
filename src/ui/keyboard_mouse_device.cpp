#include "ui/keyboard_mouse_device.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace imasim::ui {

namespace {

bool held_control(KeySet held, int control) {
  return (held >> unsigned(control)) & 1u;
}

// +1, -1 or 0 from a pair of opposite keys (both held cancel).
Real axis(KeySet held, int minus, int plus) {
  return Real(held_control(held, plus)) - Real(held_control(held, minus));
}

Real finite_or_zero(float v) {
  return std::isfinite(v) ? Real(v) : Real(0);
}

}  // namespace

void apply_keyboard(const KeyboardMapping& m, KeySet held, const KeyboardEvents& events, Real dt,
                    devices::ConsoleInput& in) {
  if (!(dt >= 0) || !std::isfinite(dt)) dt = 0;
  for (int h = 0; h < 2; ++h) {
    devices::HandInput& hand = in.hand(devices::Hand(h));
    const int base = h * kHandControlStride;
    auto control = [&](Control c) { return base + int(c); };
    const Vec3 keys(axis(held, control(Control::left_x_minus), control(Control::left_x_plus)),
                    axis(held, control(Control::left_y_minus), control(Control::left_y_plus)),
                    axis(held, control(Control::left_z_minus), control(Control::left_z_plus)));
    // A drag is a displacement; dragging down the screen (+y pixels) brings the hand nearer.
    const auto& px = events.drag_px[std::size_t(h)];
    const Vec3 drag = m.metres_per_pixel *
                      Vec3(finite_or_zero(px[0]), -finite_or_zero(px[1]), finite_or_zero(px[2]));
    const Vec3 velocity = m.speed * keys;
    hand.frame = devices::PoseFrame::hand;
    hand.velocity = dt > 0 ? Vec3(velocity + drag / dt) : velocity;
    hand.pose.translation = (hand.pose.translation + dt * velocity + drag)
                                .cwiseMax(Vec3::Constant(-m.reach))
                                .cwiseMin(Vec3::Constant(m.reach));
    hand.has_pose = true;
    hand.has_buttons = true;
    const Real jaw = axis(held, control(Control::left_jaw_open), control(Control::left_jaw_close));
    hand.jaw = std::clamp(hand.jaw + m.jaw_rate * dt * jaw, Real(0), Real(1));
    hand.clutch = held_control(held, control(Control::left_clutch));
  }
  in.pedal = held_control(held, int(Control::pedal_cut))    ? haptics::CauteryMode::cut
             : held_control(held, int(Control::pedal_coag)) ? haptics::CauteryMode::coag
                                                            : haptics::CauteryMode::off;
  in.power_w =
      std::clamp(in.power_w + m.power_step * Real(events.power_steps), m.power_min, m.power_max);
}

KeyboardMouseDevice::KeyboardMouseDevice(const KeyboardMapping& mapping, std::string bindings)
    : mapping_(mapping), bindings_(std::move(bindings)) {}

void KeyboardMouseDevice::set_held(Control control, bool held) {
  if (control >= Control::count) return;
  if (held)
    held_.fetch_or(bit(control), std::memory_order_relaxed);
  else
    held_.fetch_and(~bit(control), std::memory_order_relaxed);
}

void KeyboardMouseDevice::release_all() {
  held_.store(0, std::memory_order_relaxed);
}

void KeyboardMouseDevice::add_drag(devices::Hand hand, float dx, float dy, float dz) {
  if (!std::isfinite(dx) || !std::isfinite(dy) || !std::isfinite(dz)) return;
  const std::size_t k = 3 * std::size_t(hand);
  drag_[k].fetch_add(dx, std::memory_order_relaxed);
  drag_[k + 1].fetch_add(dy, std::memory_order_relaxed);
  drag_[k + 2].fetch_add(dz, std::memory_order_relaxed);
}

void KeyboardMouseDevice::step_power(int steps) {
  power_steps_.fetch_add(steps, std::memory_order_relaxed);
}

void KeyboardMouseDevice::reset() {
  reset_.store(true, std::memory_order_release);
}

void KeyboardMouseDevice::poll(double now_s, devices::ConsoleInput& input) {
  if (reset_.exchange(false, std::memory_order_acquire)) {
    own_ = devices::ConsoleInput{};
    for (auto& d : drag_)
      d.store(0, std::memory_order_relaxed);
    power_steps_.store(0, std::memory_order_relaxed);
  }
  KeyboardEvents events;
  for (std::size_t k = 0; k < drag_.size(); ++k)
    events.drag_px[k / 3][k % 3] = drag_[k].exchange(0, std::memory_order_relaxed);
  events.power_steps = power_steps_.exchange(0, std::memory_order_relaxed);
  // The first poll only starts the clock (and places the hands); a stall is not a long press.
  const Real dt = last_poll_s_ < 0 ? Real(0) : Real(std::min(now_s - last_poll_s_, 0.05));
  last_poll_s_ = now_s;
  apply_keyboard(mapping_, held(), events, dt, own_);
  own_.left.time_s = own_.right.time_s = now_s;
  if (drives_[0]) input.left = own_.left;
  if (drives_[1]) input.right = own_.right;
  if (drives_[2]) {
    input.pedal = own_.pedal;
    input.power_w = own_.power_w;
  }
}

devices::DeviceInfo KeyboardMouseDevice::info() const {
  devices::DeviceInfo d;
  d.kind = "keyboard";
  d.name = "keyboard and mouse";
  d.mapping = bindings_;
  d.connected = true;
  d.workspace_m = Vec3::Constant(2 * mapping_.reach);
  d.drives_left = drives_[0];
  d.drives_right = drives_[1];
  d.drives_pedal = drives_[2];
  return d;
}

}  // namespace imasim::ui
