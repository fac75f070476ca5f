#include "devices/igtl_device.hpp"

namespace imasim::devices {

IgtlDevice::IgtlDevice(const IgtlDeviceConfig& config) : config_(config), link_(config.link) {}

void IgtlDevice::poll(double, ConsoleInput& input) {
  link_.poll(input);
}

void IgtlDevice::send_force(Hand hand, const Vec3& force_n, double now_s) {
  link_.send_force(hand, force_n, now_s);
}

DeviceInfo IgtlDevice::info() const {
  const IgtlLinkConfig& c = config_.link;
  const IgtlNames& n = c.names;
  DeviceInfo d;
  d.kind = "openigtlink";
  d.name = std::string(c.role == IgtlLinkConfig::Role::server ? "server on " : "client of ") +
           c.address + ":" + std::to_string(link_.port());
  d.mapping = "TRANSFORM " + n.left_pose + " / " + n.right_pose + " -> hand poses (mm)\n" +
              "TRANSFORM " + n.left_tool + " / " + n.right_tool + " -> tool poses (mm)\n" +
              "SENSOR " + n.left_buttons + " / " + n.right_buttons + " -> [clutch, jaw 0..1]\n" +
              "SENSOR " + n.pedal + " -> [mode 0 off 1 cut 2 coag, power W]\n" + "SENSOR " +
              n.left_force + " / " + n.right_force + " <- [Fx, Fy, Fz] N";
  d.connected = link_.connected();
  d.force_feedback = true;
  d.max_force_n = config_.max_force_n;
  d.workspace_m = config_.workspace_m;
  d.drives_left = d.drives_right = d.drives_pedal = true;
  return d;
}

}  // namespace imasim::devices
