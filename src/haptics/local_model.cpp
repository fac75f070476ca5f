#include "haptics/local_model.hpp"

#include <algorithm>

namespace imasim::haptics {

namespace {

void clamp_channel(Vec3& force, Real& magnitude, Real bound) {
  magnitude = force.norm();
  if (magnitude > bound) {
    force *= bound / magnitude;
    magnitude = bound;
  }
}

}  // namespace

DeviceTip device_in_scene(const LocalModel& m, const Vec3& hand_position,
                          const Vec3& hand_velocity) {
  DeviceTip tip;
  tip.position = m.tool_anchor + m.motion_scale * (hand_position - m.hand_anchor);
  tip.velocity = m.motion_scale * hand_velocity;
  return tip;
}

ForceChannels evaluate_local_model(const LocalModel& model, const ForceModelParams& params,
                                   const DeviceTip& tip, double now_s) {
  ForceChannels sum;
  const Real elapsed = Real(std::max(0.0, now_s - model.time_s));
  const std::uint32_t count =
      std::min<std::uint32_t>(model.contact_count, std::uint32_t(kMaxLocalContacts));
  for (std::uint32_t k = 0; k < count; ++k) {
    const LocalContact& c = model.contacts[k];
    // The contact plane moved with its surface since the step.
    const Vec3 point = c.point + elapsed * c.surface_velocity;
    ContactKinematics kin;
    kin.normal = c.normal;
    kin.depth = (point - (tip.position + c.lever)).dot(c.normal);
    kin.relative_velocity = tip.velocity - c.surface_velocity;
    const ThermalForceParams* thermal = params.thermal_of(c.tissue, model.cautery);
    const ForceChannels f = contact_force(params.of(c.tissue), thermal, model.power_w, kin);
    sum.normal += f.normal;
    sum.tangential += f.tangential;
    sum.thermal += f.thermal;
  }
  clamp_channel(sum.normal, sum.normal_n, kMaxNormalForce);
  clamp_channel(sum.tangential, sum.tangential_n, kMaxTangentialForce);
  sum.thermal_n = sum.thermal.norm();
  return sum;
}

}  // namespace imasim::haptics
