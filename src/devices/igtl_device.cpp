#include "devices/igtl_device.hpp"

namespace imasim::devices {

IgtlDevice::IgtlDevice(const IgtlDeviceConfig& config) : config_(config), link_(config.link) {}

void IgtlDevice::poll(double now_s, ConsoleInput& input) {
  link_.poll(input, now_s);
}

void IgtlDevice::send_force(Hand hand, const Vec3& force_n, double now_s) {
  link_.send_force(hand, force_n, now_s);
}

std::array<bool, 3> IgtlDevice::parts_connected() const {
  return {link_.part_connected(0), link_.part_connected(1), link_.part_connected(2)};
}

void IgtlDevice::add_counts(DeviceCounts& counts) const {
  counts.add(link_.counters());
  counts.peers_seen += link_.peers_seen();
  counts.peers_dropped += link_.peers_dropped();
  counts.peers_connected += link_.peers_connected();
  counts.peers_turned_away += link_.peers_turned_away();
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
  const IgtlCounters& counted = link_.counters();
  for (std::size_t r = 0; r < kIgtlRefusals; ++r)
    if (counted.refused[r] > 0)
      d.refused_by_reason.emplace_back(igtl_refusal_name(IgtlRefusal(r)), counted.refused[r]);
  for (std::size_t k = 0; k < counted.named; ++k)
    d.refused_by_name.emplace_back(igtl_printable_name(counted.refused_names[k].name.data()),
                                   counted.refused_names[k].count);
  if (counted.refused_others > 0)
    d.refused_by_name.emplace_back("(other names)", counted.refused_others);
  d.peers_seen = link_.peers_seen();
  d.peers_dropped = link_.peers_dropped();
  d.forces_skipped = link_.forces_skipped();
  d.peers_timed_out = link_.peers_timed_out();
  d.peers_turned_away = link_.peers_turned_away();
  d.peers_connected = link_.peers_connected();
  d.reconnects = link_.reconnects();
  return d;
}

}  // namespace imasim::devices
