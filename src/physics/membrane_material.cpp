#include "physics/membrane_material.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace imasim::physics {

void MembraneMaterial::validate(const char* owner) const {
  auto require = [&](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string(owner) + ": " + what);
  };
  require(std::isfinite(youngs_modulus) && youngs_modulus > 0, "youngs_modulus must be > 0 Pa");
  require(std::isfinite(thickness) && thickness > 0, "thickness must be > 0 m");
  require(std::isfinite(bending_stiffness) && bending_stiffness >= 0,
          "bending_stiffness must be >= 0 N m");
  require(poisson_ratio >= 0 && poisson_ratio < Real(0.5), "poisson_ratio must be in [0, 0.5)");
}

Real MembraneMaterial::effective_bending_stiffness() const {
  if (bending_stiffness > 0) return bending_stiffness;
  const Real t = thickness;
  return youngs_modulus * t * t * t / (12 * (1 - poisson_ratio * poisson_ratio));
}

}  // namespace imasim::physics
