#include "haptics/force_params.hpp"

namespace imasim::haptics {

const ThermalForceParams* ForceModelParams::thermal_of(TissueKind kind, CauteryMode mode) const {
  switch (mode) {
    case CauteryMode::cut:
      return &thermal_cut[std::size_t(kind)];
    case CauteryMode::coag:
      return &thermal_coag[std::size_t(kind)];
    case CauteryMode::off:
      return nullptr;
  }
  return nullptr;
}

// Reasoning and sources: docs/haptics.md ("Default parameters").
ForceModelParams default_force_model_params() {
  ForceModelParams p;
  //          stiffness (N/m), damping (N s/m), friction (-), cutting resistance (N s/m)
  // Fascia and fat: the stiffness a hook's tip meets on fat (Boussinesq's punch on Samani's
  // 3.25 kPa), damped with the 7-10 ms time constants the stiffer values had.
  p.contact[std::size_t(TissueKind::fascia)] = {4.3, 0.03, 0.2, 5};
  p.contact[std::size_t(TissueKind::fat)] = {4.3, 0.04, 0.1, 2};
  // The IMA: a beam (its wall's E I) on its layer of fat (Hetenyi's point load on an elastic
  // foundation), in series with its wall tensed by the blood's pressure (Laplace) under the tip:
  // 34 N/m; damped at 10 ms, the time constant its former 200 N/m had.
  p.contact[std::size_t(TissueKind::ima)] = {34, 0.34, 0.15, 8};
  p.contact[std::size_t(TissueKind::heart)] = {400, 3, 0.1, 5};
  p.contact[std::size_t(TissueKind::chest_wall)] = {1000, 5, 0.3, 10};
  //          k_t (N/W), alpha (1/m)
  for (std::size_t k = 0; k < kTissueKinds; ++k) {
    p.thermal_cut[k] = {0.004, 1000};
    p.thermal_coag[k] = {0.008, 500};
  }
  // Fat vaporises readily under the blade (less resistance); the chest wall is not cut.
  p.thermal_cut[std::size_t(TissueKind::fat)] = {0.002, 1000};
  p.thermal_cut[std::size_t(TissueKind::chest_wall)] = {0.006, 1000};
  return p;
}

}  // namespace imasim::haptics
