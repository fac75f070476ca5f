#include "scene/ports.hpp"

namespace imasim::scene {

std::vector<Port> default_ports(const Vec3& target) {
  // Left chest wall, about 8-10 cm lateral of the vessel, in the 3rd-6th intercostal spaces.
  std::vector<Port> ports = {
      {"camera", PortKind::camera, Vec3(Real(0.09), Real(-0.02), Real(0.08)), Vec3::Zero()},
      {"left_instrument", PortKind::instrument, Vec3(Real(0.10), Real(-0.02), Real(0.00)),
       Vec3::Zero()},
      {"right_instrument", PortKind::instrument, Vec3(Real(0.09), Real(-0.02), Real(0.16)),
       Vec3::Zero()},
      {"assistant", PortKind::assistant, Vec3(Real(0.12), Real(-0.03), Real(0.20)), Vec3::Zero()},
  };
  aim_ports(ports, target);
  return ports;
}

void aim_ports(std::vector<Port>& ports, const Vec3& target) {
  for (Port& p : ports)
    p.direction = (target - p.position).normalized();
}

const char* to_string(PortKind kind) {
  switch (kind) {
    case PortKind::camera:
      return "camera";
    case PortKind::instrument:
      return "instrument";
    case PortKind::assistant:
      return "assistant";
  }
  return "unknown";
}

}  // namespace imasim::scene
