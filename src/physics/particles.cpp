#include "physics/particles.hpp"

#include <stdexcept>

namespace imasim::physics {

std::uint32_t Particles::add(const Vec3& x, Real mass, ObjectId owner) {
  if (!(mass > 0)) throw std::invalid_argument("particle mass must be positive");
  if (!x.allFinite()) throw std::invalid_argument("particle position must be finite");
  const auto index = static_cast<std::uint32_t>(position.size());
  position.push_back(x);
  predicted.push_back(x);
  velocity.push_back(Vec3::Zero());
  rest_position.push_back(x);
  inverse_mass.push_back(Real(1) / mass);
  object.push_back(owner);
  return index;
}

}  // namespace imasim::physics
