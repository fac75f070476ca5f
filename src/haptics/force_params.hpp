#pragma once
// The force model's parameters per tissue kind and cautery mode, with documented defaults
// (docs/haptics.md gives the source or reasoning of each).
#include <array>

#include "haptics/force_law.hpp"

namespace imasim::haptics {

struct ForceModelParams {
  std::array<ContactForceParams, kTissueKinds> contact;
  std::array<ThermalForceParams, kTissueKinds> thermal_cut, thermal_coag;

  const ContactForceParams& of(TissueKind kind) const { return contact[std::size_t(kind)]; }
  // Null while the cautery is off.
  const ThermalForceParams* thermal_of(TissueKind kind, CauteryMode mode) const;
};

ForceModelParams default_force_model_params();

}  // namespace imasim::haptics
