#pragma once
// OpenIGTLink as an InputDevice: a tracker or desktop haptic devices over one IgtlLink, driving
// both hands and the pedal by the message names of IgtlNames, and receiving each hand's force.
#include <memory>

#include "devices/igtl_link.hpp"
#include "devices/input_device.hpp"

namespace imasim::devices {

struct IgtlDeviceConfig {
  IgtlLinkConfig link;
  Real max_force_n = Real(3.3);  // what the peer's devices can render (desktop class) (unit: N)
  Vec3 workspace_m = Vec3(0.16, 0.12, 0.12);
};

class IgtlDevice final : public InputDevice {
 public:
  explicit IgtlDevice(const IgtlDeviceConfig& config);  // throws IgtlLinkError
  void poll(double now_s, ConsoleInput& input) override;
  void send_force(Hand hand, const Vec3& force_n, double now_s) override;
  bool connected() const override { return link_.connected(); }
  std::array<bool, 3> parts_connected() const override;
  void add_counts(DeviceCounts& counts) const override;
  DeviceInfo info() const override;
  // Bit r: IgtlRefusal r.
  std::uint32_t refusal_reasons() const override { return link_.counters().reasons_seen(); }
  std::uint64_t refused_total() const override { return link_.counters().refused_total(); }
  const IgtlLink& link() const { return link_; }

 private:
  IgtlDeviceConfig config_;
  IgtlLink link_;
};

}  // namespace imasim::devices
