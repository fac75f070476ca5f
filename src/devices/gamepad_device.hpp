#pragma once
// Gamepads and joysticks through SDL2: the first game controller SDL finds drives
// both hands and the pedal by GamepadMapping; the force on the hands comes back as the pad's
// rumble (a vibration cue proportional to the larger force, not a force). Works without a
// display (SDL's game-controller subsystem needs no video). A pad plugged in later is picked up;
// one pulled out reads as not connected.
#include <array>
#include <string>
#include <vector>

#include "devices/gamepad_mapping.hpp"
#include "devices/input_device.hpp"

namespace imasim::devices {

class GamepadDevice final : public InputDevice {
 public:
  // Starts SDL's game-controller subsystem; throws std::runtime_error when SDL cannot.
  explicit GamepadDevice(const GamepadMapping& mapping = {});
  ~GamepadDevice() override;
  GamepadDevice(const GamepadDevice&) = delete;
  GamepadDevice& operator=(const GamepadDevice&) = delete;

  void poll(double now_s, ConsoleInput& input) override;
  void send_force(Hand hand, const Vec3& force_n, double now_s) override;
  bool connected() const override { return controller_ != nullptr; }
  DeviceInfo info() const override;
  void polling_thread_ending() override;  // SDL's thread-local state of that thread

  // The names of the game controllers SDL sees now (for `imasim devices`).
  static std::vector<std::string> list_controllers();

 private:
  void open_first();

  GamepadMapping mapping_;
  void* controller_ = nullptr;  // SDL_GameController*
  std::string name_;
  double last_poll_s_ = -1;
  std::array<Real, 2> force_{0, 0};
  double last_rumble_s_ = -1;
};

}  // namespace imasim::devices
