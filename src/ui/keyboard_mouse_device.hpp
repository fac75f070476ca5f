#pragma once
// The keyboard and mouse as a two-handed console, on the gamepad's model
// (devices/gamepad_mapping.hpp): a held movement key moves its hand at `speed` along one axis of
// the console's hand frame (the arm's 3:1 scaling and clutch do the rest), a mouse drag moves a
// hand by its pixels; jaw keys close or open a hand's jaws at `jaw_rate` while held; the pedal
// keys press cut or coagulation while held; power keys step the generator's setting.
// The window thread writes the keys' state (atomics); the 1 kHz loop polls the device.
#include <array>
#include <atomic>
#include <cstdint>
#include <string>

#include "devices/input_device.hpp"

namespace imasim::ui {

// What a key can do to the console, one bit each in a KeySet.
enum class Control : std::uint8_t {
  left_x_minus,
  left_x_plus,
  left_y_minus,
  left_y_plus,
  left_z_minus,
  left_z_plus,
  left_jaw_close,
  left_jaw_open,
  left_clutch,
  right_x_minus,
  right_x_plus,
  right_y_minus,
  right_y_plus,
  right_z_minus,
  right_z_plus,
  right_jaw_close,
  right_jaw_open,
  right_clutch,
  pedal_cut,
  pedal_coag,
  count
};
inline constexpr int kControlCount = int(Control::count);
// The controls of each hand are laid out alike: the right hand's are the left's plus this.
inline constexpr int kHandControlStride = int(Control::right_x_minus);

using KeySet = std::uint32_t;  // bit c: control c held
constexpr KeySet bit(Control c) {
  return KeySet(1) << unsigned(c);
}

struct KeyboardMapping {
  Real speed = Real(0.03);  // hand speed while a movement key is held (unit: m/s)
  Real reach = Real(0.15);  // the hand stays within this of its start per axis (unit: m)
  Real jaw_rate = 2;        // jaw travel (0 open .. 1 closed) per second held (unit: 1/s)
  Real metres_per_pixel = Real(1e-4);   // hand motion per pixel of mouse drag (unit: m)
  Real power_step = 5;                  // per press of a power key (unit: W)
  Real power_min = 30, power_max = 50;  // the generator's range (surgery/cautery.hpp, unit: W)
};

// What changed since the last update besides the held keys: mouse drags per hand (pixels: x
// right, y down, z depth) and power key presses (+1 a press of "up", -1 of "down").
struct KeyboardEvents {
  std::array<std::array<float, 3>, 2> drag_px{};
  int power_steps = 0;
};

// One update over `dt` seconds (a pure function, the device's whole mapping): moves each hand,
// integrates its jaws, sets clutches, the pedal and the power. Hands are in the console's hand
// frame: x right, y away from the operator, z up; their velocity is the keys'.
void apply_keyboard(const KeyboardMapping& mapping, KeySet held, const KeyboardEvents& events,
                    Real dt, devices::ConsoleInput& input);

class KeyboardMouseDevice final : public devices::InputDevice {
 public:
  // `bindings`: which key does what, one line a control (the info's mapping).
  explicit KeyboardMouseDevice(const KeyboardMapping& mapping = {}, std::string bindings = {});

  // Which parts of the console it drives (all by default); the rest it leaves to the other
  // devices (a gamepad's hands, a foot switch's pedal). Before the console starts.
  void set_drives(bool left, bool right, bool pedal) { drives_ = {left, right, pedal}; }

  // Window thread: key and mouse state (lock-free; never waits on the loop).
  void set_held(Control control, bool held);
  void release_all();  // the window lost focus: no key stays held
  void add_drag(devices::Hand hand, float dx_px, float dy_px, float dz_px);
  void step_power(int steps);
  // Puts both hands back at their start, jaws open, power at its default (a restarted session).
  void reset();
  KeySet held() const { return held_.load(std::memory_order_relaxed); }

  // Loop thread.
  void poll(double now_s, devices::ConsoleInput& input) override;
  void send_force(devices::Hand, const Vec3&, double) override {}
  bool connected() const override { return true; }
  devices::DeviceInfo info() const override;

 private:
  KeyboardMapping mapping_;
  std::string bindings_;
  std::atomic<KeySet> held_{0};
  std::array<std::atomic<float>, 6> drag_{};  // per hand x, y, z, summed until polled
  std::atomic<int> power_steps_{0};
  std::atomic<bool> reset_{false};
  std::array<bool, 3> drives_{true, true, true};  // left, right, pedal and power
  // Loop thread: the keyboard's own hands and pedal, copied into the console's input for the
  // parts it drives (another device writes only when its messages come).
  devices::ConsoleInput own_;
  double last_poll_s_ = -1;
};

}  // namespace imasim::ui
