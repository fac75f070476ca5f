#pragma once
// Force Dimension devices (omega, sigma, delta, novint Falcon; DHD API) as an InputDevice:
// one device per hand, by its index among those connected. Compiled only with
// IMASIM_FORCE_DIMENSION=ON and the SDK installed (CMake finds dhdc.h and libdhd);
// docs/haptics.md. The DHD API is called from the 1 kHz loop itself (it is synchronous). Device
// frame as the vendor's (metres), read as the console hand's frame; a gripper's opening drives
// the jaws (else button 0 closes them while held); button 1 is the clutch.
#include <string>

#include "devices/input_device.hpp"

namespace imasim::devices {

class ForceDimensionDevice final : public InputDevice {
 public:
  // Throws std::runtime_error with the DHD error when the device cannot be opened.
  ForceDimensionDevice(int index, Hand hand);
  ~ForceDimensionDevice() override;
  ForceDimensionDevice(const ForceDimensionDevice&) = delete;
  ForceDimensionDevice& operator=(const ForceDimensionDevice&) = delete;

  void poll(double now_s, ConsoleInput& input) override;
  void send_force(Hand hand, const Vec3& force_n, double now_s) override;
  bool connected() const override { return ok_; }
  DeviceInfo info() const override;

 private:
  int id_ = -1;
  Hand hand_;
  std::string name_;
  bool gripper_ = false;
  bool ok_ = false;
};

}  // namespace imasim::devices
