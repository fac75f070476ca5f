#pragma once
// 3D mice (SpaceMouse, SpaceNavigator) through libspnav and the spacenavd daemon: one
// hand (the right by default) moved by the cap's push as a velocity in six degrees of freedom,
// its two buttons for the jaw (held = closed) and the clutch (held). The daemon reports
// displacements of the cap, about +-350 at full push. Without the daemon the device reads as not
// connected and changes nothing; it retries every second.
#include <array>

#include "devices/input_device.hpp"

namespace imasim::devices {

struct SpaceMouseMapping {
  Hand hand = Hand::right;
  Real full_scale = 350;        // the daemon's reading at full push
  Real speed = Real(0.04);      // at full push (unit: m/s)
  Real turn_rate = Real(1.0);   // at full twist (unit: rad/s)
  Real dead_zone = Real(0.05);  // share of full scale read as rest
  int jaw_button = 0, clutch_button = 1;
};

// One motion reading (x y z rx ry rz, the daemon's units) applied over dt: the hand's velocity,
// its position and orientation.
void apply_space_motion(const SpaceMouseMapping& mapping, const std::array<int, 6>& motion, Real dt,
                        HandInput& hand);

class SpaceMouseDevice final : public InputDevice {
 public:
  explicit SpaceMouseDevice(const SpaceMouseMapping& mapping = {});
  ~SpaceMouseDevice() override;
  SpaceMouseDevice(const SpaceMouseDevice&) = delete;
  SpaceMouseDevice& operator=(const SpaceMouseDevice&) = delete;

  void poll(double now_s, ConsoleInput& input) override;
  void send_force(Hand, const Vec3&, double) override {}  // no actuators
  bool connected() const override { return open_; }
  DeviceInfo info() const override;

 private:
  SpaceMouseMapping mapping_;
  bool open_ = false;
  double last_try_s_ = -10, last_poll_s_ = -1;
  std::array<int, 6> motion_{};  // the latest reading (the daemon sends changes only)
  std::array<bool, 2> held_{false, false};
};

}  // namespace imasim::devices
