#pragma once
// How a constraint responds: XPBD with a compliance, or classic PBD with a stiffness in [0, 1].
// The two are separate named fields, never one number read two ways.
#include <cstdint>

#include "math/types.hpp"

namespace imasim::physics {

enum class Response : std::uint8_t { xpbd, pbd };

struct ConstraintMaterial {
  Response response = Response::xpbd;
  // XPBD compliance alpha = 1/k. Its unit follows the constraint value C: m/N for distance and
  // attachment (C in m), rad/(N*m) for dihedral bending (C in rad). 0 = rigid.
  Real compliance = 0;
  // PBD stiffness in [0, 1]: the fraction of the constraint error removed per projection.
  Real pbd_stiffness = 1;

  static ConstraintMaterial xpbd(Real compliance_value) {
    return {Response::xpbd, compliance_value, Real(1)};
  }
  static ConstraintMaterial pbd(Real stiffness) { return {Response::pbd, Real(0), stiffness}; }
};

using MaterialId = std::uint32_t;

// A material as the projection uses it for one substep of length h:
//   d_lambda = (-scale * C - alpha_tilde * lambda) / (sum_i w_i |grad_i C|^2 + alpha_tilde)
// XPBD: scale = 1, alpha_tilde = alpha / h^2 (Macklin et al. 2016, eq. 18).
// PBD:  scale = k, alpha_tilde = 0, which is Mueller et al.'s projection scaled by k.
struct ProjectionTerms {
  Real scale = 1;
  Real alpha_tilde = 0;
};

inline ProjectionTerms projection_terms(const ConstraintMaterial& m, Real h) {
  if (m.response == Response::pbd) return {m.pbd_stiffness, Real(0)};
  return {Real(1), m.compliance / (h * h)};
}

// A row projected once every `stride` substeps of length h, inside one of them: its correction
// is the impulse of all `stride` (force f over stride h moves a particle by f stride h^2 / m in
// the substep that applies it), so XPBD's alpha_tilde = alpha / (stride h^2). PBD as above.
inline ProjectionTerms strided_projection_terms(const ConstraintMaterial& m, Real h,
                                                std::uint32_t stride) {
  if (m.response == Response::pbd) return {m.pbd_stiffness, Real(0)};
  return {Real(1), m.compliance / (Real(stride) * h * h)};
}

}  // namespace imasim::physics
