#pragma once
// A membrane (fascia, vessel wall) in physical units, mapped to the compliances of its distance
// (eq. 2) and dihedral (eq. 3) constraints so that its response does not depend on the mesh
// (SPEC S1). The material holds the per-unit-geometry compliance, each row a dimensionless scale:
//   stretch: k_e = E t sum_T A_T / |e|^2     (sum over the triangles T on edge e)
//            -> material 1/(E t) (unit: m/N), row scale |e|^2 / sum_T A_T;
//   bending: k_e = D |e|^2 / (A_1 + A_2)     (interior edges)
//            -> material 1/D (unit: rad/(N m)), row scale (A_1 + A_2) / |e|^2.
// Both ratios are scale-free, so a refined mesh keeps the sheet's modulus. On an equilateral mesh
// the spring network has exactly the membrane's E t (with Poisson's ratio 1/3), and the hinges the
// plate's bending stiffness D (Seung and Nelson 1988); on the grid of grid_rectangle.hpp the
// measured moduli are given in docs/physics.md.
#include "math/types.hpp"
#include "physics/material.hpp"

namespace imasim::physics {

struct MembraneMaterial {
  Real youngs_modulus = 0;          // E (unit: Pa)
  Real thickness = 0;               // t (unit: m)
  Real bending_stiffness = 0;       // D (unit: N m); 0 = the plate's, E t^3 / (12 (1 - nu^2))
  Real poisson_ratio = Real(0.45);  // nu, for the plate's D only (soft tissue: nearly 0.5)

  // Throws std::invalid_argument naming the field.
  void validate(const char* owner) const;
  Real effective_bending_stiffness() const;  // D (unit: N m)
  ConstraintMaterial stretch() const {
    return ConstraintMaterial::xpbd(1 / (youngs_modulus * thickness));
  }
  ConstraintMaterial bend() const {
    return ConstraintMaterial::xpbd(1 / effective_bending_stiffness());
  }
};

// Row scales from rest geometry: |e|^2 and the summed area of the triangles on the edge.
inline Real stretch_compliance_scale(Real edge_length2, Real adjacent_area) {
  return edge_length2 / adjacent_area;
}
inline Real bend_compliance_scale(Real edge_length2, Real adjacent_area) {
  return adjacent_area / edge_length2;
}

}  // namespace imasim::physics
