#pragma once
// OpenHaptics (3D Systems Touch, Touch X; HD API) as an InputDevice: one device per
// hand, named as in the vendor's configuration ("Default Device", or the names its setup tool
// gave two devices). Compiled only with IMASIM_OPENHAPTICS=ON and the SDK installed (CMake finds
// HD/hd.h and libHD); docs/haptics.md. The HD API runs its own 1 kHz servo thread: a callback
// there reads the stylus and applies the newest force; the two loops exchange them lock-free.
// Device frame as the vendor's (millimetres, y up, z toward the user), read as the console
// hand's frame; stylus button 1 closes the jaws while held, button 2 is the clutch.
#include <memory>
#include <string>

#include "devices/input_device.hpp"

namespace imasim::devices {

class OpenHapticsDevice final : public InputDevice {
 public:
  // Throws std::runtime_error with the HD API's error when the device cannot be opened.
  OpenHapticsDevice(const std::string& device_name, Hand hand);
  ~OpenHapticsDevice() override;
  OpenHapticsDevice(const OpenHapticsDevice&) = delete;
  OpenHapticsDevice& operator=(const OpenHapticsDevice&) = delete;

  void poll(double now_s, ConsoleInput& input) override;
  void send_force(Hand hand, const Vec3& force_n, double now_s) override;
  bool connected() const override;
  DeviceInfo info() const override;

  struct Servo;  // the servo thread's side (openhaptics_device.cpp)

 private:
  std::string name_;
  Hand hand_;
  std::unique_ptr<Servo> servo_;
};

}  // namespace imasim::devices
