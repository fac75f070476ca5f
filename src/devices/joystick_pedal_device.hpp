#pragma once
// A USB foot switch (or any joystick's buttons) as the console's pedals through SDL2 (issue
// 13), mapped by PedalMapping. It drives the pedal and, when a clutch pedal is mapped, both
// clutches; the hands come from another device (OpenIGTLink, the emulator, a gamepad). Works
// without a display. A switch plugged in later is picked up; one pulled out reads as not
// connected and its pedals as released (no energy without a foot on the pedal).
#include <array>
#include <string>

#include "devices/input_device.hpp"
#include "devices/pedal_mapping.hpp"

namespace imasim::devices {

class JoystickPedalDevice final : public InputDevice {
 public:
  // Starts SDL's joystick subsystem; throws std::runtime_error when SDL cannot.
  explicit JoystickPedalDevice(const PedalMapping& mapping = {});
  ~JoystickPedalDevice() override;
  JoystickPedalDevice(const JoystickPedalDevice&) = delete;
  JoystickPedalDevice& operator=(const JoystickPedalDevice&) = delete;

  void poll(double now_s, ConsoleInput& input) override;
  void send_force(Hand, const Vec3&, double) override {}  // no actuators
  bool connected() const override { return joystick_ != nullptr; }
  DeviceInfo info() const override;
  void polling_thread_ending() override;  // SDL's thread-local state of that thread

 private:
  void open_matching();

  PedalMapping mapping_;
  void* joystick_ = nullptr;  // SDL_Joystick*
  std::string name_;
  std::array<bool, kNoPedalButton> held_{};
};

// Whether a joystick called `name` is the one `pattern` asks for (PedalMapping::joystick).
bool joystick_name_matches(const std::string& pattern, const std::string& name,
                           bool is_game_controller);

}  // namespace imasim::devices
