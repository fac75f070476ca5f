#include "haptics/force_law.hpp"

#include <algorithm>
#include <cmath>

namespace imasim::haptics {

const char* tissue_kind_name(TissueKind kind) {
  switch (kind) {
    case TissueKind::fascia:
      return "fascia";
    case TissueKind::fat:
      return "fat";
    case TissueKind::ima:
      return "ima";
    case TissueKind::heart:
      return "heart";
    case TissueKind::chest_wall:
      return "chest_wall";
  }
  return "?";
}

ForceChannels contact_force(const ContactForceParams& tissue, const ThermalForceParams* thermal,
                            Real power_w, const ContactKinematics& contact) {
  ForceChannels f;
  if (!(contact.depth > 0)) return f;  // out of contact (or NaN): no tissue, no force
  const Vec3& n = contact.normal;
  // v_n: the rate at which the depth grows, i.e. the device moving against the normal.
  const Real v_n = -contact.relative_velocity.dot(n);
  const Vec3 v_t = contact.relative_velocity + v_n * n;  // the part along the surface
  // eq. 17 (unit: N)
  f.normal_n =
      std::clamp(tissue.stiffness * contact.depth + tissue.damping * v_n, Real(0), kMaxNormalForce);
  f.normal = f.normal_n * n;
  // eq. 18 (unit: N), against the sliding direction
  const Real speed = v_t.norm();
  f.tangential_n = std::clamp(tissue.friction * f.normal_n + tissue.cutting_resistance * speed,
                              Real(0), kMaxTangentialForce);
  f.tangential = -f.tangential_n * v_t / std::max(speed, kSlidingSpeedScale);
  // eq. 19 (unit: N), with d the depth into the tissue
  if (thermal != nullptr && power_w > 0) {
    f.thermal_n = thermal->coefficient * power_w * std::exp(-thermal->decay * contact.depth);
    f.thermal = f.thermal_n * n;
  }
  return f;
}

}  // namespace imasim::haptics
