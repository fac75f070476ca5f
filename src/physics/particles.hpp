#pragma once
// Particle data as structure of arrays: each attribute is one contiguous array indexed by
// particle id, so a pass that touches one attribute streams through memory.
#include <cstdint>
#include <vector>

#include "math/types.hpp"

namespace imasim::physics {

using ObjectId = std::uint16_t;

struct Particles {
  std::vector<Vec3> position;       // x (unit: m)
  std::vector<Vec3> predicted;      // p, the position being projected within a substep (unit: m)
  std::vector<Vec3> velocity;       // v (unit: m/s)
  std::vector<Vec3> rest_position;  // x0, the reference configuration (unit: m)
  std::vector<Real> inverse_mass;   // w = 1/m (unit: 1/kg); 0 = fixed particle
  std::vector<ObjectId> object;     // owning object (per-object gravity and damping)

  std::size_t size() const { return position.size(); }

  // Adds a particle at rest at x; returns its index. Set-up only (allocates).
  std::uint32_t add(const Vec3& x, Real mass, ObjectId owner);
  void fix(std::uint32_t i) { inverse_mass[i] = 0; }
  bool is_fixed(std::uint32_t i) const { return inverse_mass[i] == 0; }
};

// Sum of m v^2 / 2 over the dynamic particles (unit: J).
double kinetic_energy(const Particles& particles);

}  // namespace imasim::physics
