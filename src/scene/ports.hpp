#pragma once
// Ports on the left chest wall (paper Fig. 2e): where the endoscope and the instruments enter.
// Robotic instruments pivot about their port (remote centre of motion, SPEC S3 reading).
#include <string>
#include <vector>

#include "math/types.hpp"

namespace imasim::scene {

enum class PortKind { camera, instrument, assistant };

struct Port {
  std::string name;
  PortKind kind = PortKind::instrument;
  Vec3 position = Vec3::Zero();     // the pivot on the chest wall (unit: m)
  Vec3 direction = -Vec3::UnitY();  // unit, into the thoracic cavity
};

// Camera port between the two instrument ports, assistant port caudal to them, all on the left
// chest wall, aimed at the middle of the harvest segment (scene frame of thorax_scene.hpp).
std::vector<Port> default_ports(const Vec3& target);

// Points every port's direction at `target`.
void aim_ports(std::vector<Port>& ports, const Vec3& target);

const char* to_string(PortKind kind);

}  // namespace imasim::scene
