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

double kinetic_energy(const Particles& P) {
  double energy = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.inverse_mass[i] > 0)
      energy += 0.5 * double(P.velocity[i].squaredNorm() / P.inverse_mass[i]);
  }
  return energy;
}

}  // namespace imasim::physics
