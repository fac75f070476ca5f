#pragma once
// A strain-stiffening spring: the edge of a collagen membrane (fascia). Crimped fibres straighten
// and are recruited one by one as it is stretched (docs/tissue.md), so its tangent stiffness
// rises from the toe region's k_t at rest to the linear region's k_l at the toe strain eps_t, and
// stays k_l beyond; in compression it is k_t. With eps = l / l0 - 1 and s = eps / eps_t:
//   k(eps) = k_t + (k_l - k_t) S(s),   S(s) = 3 s^2 - 2 s^3 on [0, 1], 0 below, 1 above,
//   T(l) = l0 [k_t eps + (k_l - k_t) eps_t I(s)],   I = integral of S (s^3 - s^4 / 2 on [0, 1]),
//   E(l) = l0^2 [k_t eps^2 / 2 + (k_l - k_t) eps_t^2 J(s)],   J = integral of I.
// The recruitment is smooth (k is continuous), so the Hessian of Newton's method
// (implicit_membrane.hpp) does not jump 26-fold where an edge crosses into its linear region.
#include <algorithm>

#include "math/types.hpp"

namespace imasim::physics {

struct StiffeningSpring {
  Real rest_length = 0;       // l0 (unit: m)
  Real toe_stiffness = 0;     // k_t (unit: N/m)
  Real linear_stiffness = 0;  // k_l >= k_t (unit: N/m)
  Real toe_strain = 0;        // eps_t > 0 (dimensionless)
};

namespace stiffening_detail {
// s = eps / eps_t and the recruitment's S, I, J at s (s >= 0).
struct Recruitment {
  Real S, I, J;
};
inline Recruitment recruitment(Real s) {
  if (s <= 1) {
    const Real s2 = s * s, s3 = s2 * s;
    return {3 * s2 - 2 * s3, s3 - s3 * s / 2, s3 * s / 4 - s3 * s2 / 10};
  }
  const Real past = s - 1;
  return {1, Real(0.5) + past, Real(0.15) + past / 2 + past * past / 2};
}
}  // namespace stiffening_detail

// dT/dl at l (unit: N/m).
inline Real stiffness_at(const StiffeningSpring& sp, Real length) {
  const Real eps = length / sp.rest_length - 1;
  if (eps <= 0) return sp.toe_stiffness;
  return sp.toe_stiffness + (sp.linear_stiffness - sp.toe_stiffness) *
                                stiffening_detail::recruitment(eps / sp.toe_strain).S;
}

// T(l) (unit: N), positive in tension.
inline Real tension(const StiffeningSpring& sp, Real length) {
  const Real eps = length / sp.rest_length - 1;
  Real t = sp.toe_stiffness * eps;
  if (eps > 0) {
    t += (sp.linear_stiffness - sp.toe_stiffness) * sp.toe_strain *
         stiffening_detail::recruitment(eps / sp.toe_strain).I;
  }
  return sp.rest_length * t;
}

// E(l), the integral of T from l0 (unit: J).
inline Real energy(const StiffeningSpring& sp, Real length) {
  const Real eps = length / sp.rest_length - 1;
  Real e = sp.toe_stiffness * eps * eps / 2;
  if (eps > 0) {
    e += (sp.linear_stiffness - sp.toe_stiffness) * sp.toe_strain * sp.toe_strain *
         stiffening_detail::recruitment(eps / sp.toe_strain).J;
  }
  return sp.rest_length * sp.rest_length * e;
}

// Whether the edge is past its toe, in its linear region.
inline bool past_toe(const StiffeningSpring& sp, Real length) {
  return length > sp.rest_length * (1 + sp.toe_strain);
}

}  // namespace imasim::physics
