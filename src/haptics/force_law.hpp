#pragma once
// The paper's dual-channel force (2.4.4 of "Dynamic Virtual Simulation with Real-time Haptic
// Feedback for Robotic Internal Mammary Artery Harvesting", S.W., T.R., N.C., R.W., L.Z.; MDPI,
// no DOI in our copy):
//   eq. 17  F_n = k_d d + c_d v_n,        clamped to [0, 5] N, along the contact normal
//   eq. 18  F_t = mu F_n + k_c |v_t|,     clamped to [0, 2] N, against the tangential velocity
//   eq. 19  F_therm = k_t P exp(-alpha d), while the cautery is active, along the normal
// d is the depth of the device past the contact surface (the proxy on it) along the normal;
// v_n = the rate at which d grows; v_t the device's velocity along the surface, both relative
// to the surface (SPEC S5). Out of contact (d <= 0) every channel is zero.
#include "haptics/tissue_kind.hpp"
#include "math/types.hpp"

namespace imasim::haptics {

inline constexpr Real kMaxNormalForce = 5;      // eq. 17's bound (unit: N)
inline constexpr Real kMaxTangentialForce = 2;  // eq. 18's bound (unit: N)
// Below this sliding speed the tangential force's direction fades out with the speed instead of
// flipping with the sign of noise (a regularised Coulomb friction; unit: m/s).
inline constexpr Real kSlidingSpeedScale = Real(1e-3);

// Mechanical parameters of one tissue kind.
struct ContactForceParams {
  Real stiffness = 0;           // k_d, eq. 17 (unit: N/m)
  Real damping = 0;             // c_d, eq. 17 (unit: N s/m)
  Real friction = 0;            // mu, eq. 18 (dimensionless)
  Real cutting_resistance = 0;  // k_c, eq. 18 (unit: N s/m)
};

// Thermal parameters of one tissue kind in one cautery mode.
struct ThermalForceParams {
  Real coefficient = 0;  // k_t, eq. 19 (unit: N/W)
  Real decay = 0;        // alpha, eq. 19 (unit: 1/m)
};

// One contact as the haptic loop sees it.
struct ContactKinematics {
  Real depth = 0;                         // d (unit: m); > 0 in contact
  Vec3 normal = Vec3::UnitZ();            // unit, out of the tissue (the way the tissue pushes)
  Vec3 relative_velocity = Vec3::Zero();  // device minus surface (unit: m/s)
};

// The three channels as vectors (unit: N) and the magnitudes eq. 17-19 give.
struct ForceChannels {
  Vec3 normal = Vec3::Zero();
  Vec3 tangential = Vec3::Zero();
  Vec3 thermal = Vec3::Zero();
  Real normal_n = 0, tangential_n = 0, thermal_n = 0;  // (unit: N)

  Vec3 total() const { return normal + tangential + thermal; }
};

// eq. 17-19 for one contact. `thermal` is null, or `power_w` 0, while the cautery is off.
ForceChannels contact_force(const ContactForceParams& tissue, const ThermalForceParams* thermal,
                            Real power_w, const ContactKinematics& contact);

}  // namespace imasim::haptics
