#pragma once
// The shared XPBD/PBD projection step for one scalar constraint (see material.hpp).
#include "math/types.hpp"
#include "physics/material.hpp"

namespace imasim::physics {

// Particle positions, inverse masses and per-material projection terms for one substep.
struct ProjectionContext {
  Vec3* positions = nullptr;               // predicted positions p (unit: m)
  const Real* inverse_mass = nullptr;      // (unit: 1/kg)
  const ProjectionTerms* terms = nullptr;  // indexed by MaterialId
};

// The terms of a row whose compliance is its material's times `compliance_scale`.
inline ProjectionTerms scaled(const ProjectionTerms& t, Real compliance_scale) {
  return {t.scale, t.alpha_tilde * compliance_scale};
}

// Returns the multiplier increment for a constraint with value c and weighted gradient norm
// w_grad2 = sum_i w_i |grad_i C|^2; lambda is the accumulated multiplier of this substep.
inline Real lambda_increment(const ProjectionTerms& t, Real c, Real w_grad2, Real lambda) {
  return (-t.scale * c - t.alpha_tilde * lambda) / (w_grad2 + t.alpha_tilde);
}

}  // namespace imasim::physics
