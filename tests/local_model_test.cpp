// The local model between two physics steps: the force against a moving contact plane matches
// the closed form at every millisecond.
#include <gtest/gtest.h>

#include "haptics/local_model.hpp"

namespace imasim::haptics {
namespace {

LocalModel one_contact(const Vec3& surface_velocity) {
  LocalModel m;
  m.time_s = 1.0;
  m.contact_count = 1;
  m.contacts[0].point = Vec3(0, 0, 0.01);
  m.contacts[0].normal = Vec3::UnitZ();
  m.contacts[0].surface_velocity = surface_velocity;
  m.contacts[0].tissue = TissueKind::heart;
  return m;
}

TEST(LocalModel, ForceAgainstAMovingWallMatchesTheClosedFormEachMillisecond) {
  const ForceModelParams params = default_force_model_params();
  const ContactForceParams& heart = params.of(TissueKind::heart);
  // The heart wall rises at 20 mm/s toward a still device 2 mm below the surface at the step.
  const LocalModel m = one_contact(Vec3(0, 0, 0.02));
  DeviceTip tip;
  tip.position = Vec3(0.003, 0, 0.008);
  for (int ms = 0; ms <= 5; ++ms) {
    const double now = 1.0 + ms * 1e-3;
    const ForceChannels f = evaluate_local_model(m, params, tip, now);
    // d(t) = 2 mm + 20 mm/s t; v_n = +20 mm/s (the depth grows).
    const Real d = 0.002 + 0.02 * ms * 1e-3;
    const Real expected = heart.stiffness * d + heart.damping * 0.02;
    EXPECT_NEAR(f.normal_n, expected, 1e-12) << ms;
    EXPECT_NEAR(f.normal.z(), expected, 1e-12) << ms;
    EXPECT_EQ(f.tangential, Vec3::Zero()) << ms;  // no sliding
  }
}

TEST(LocalModel, FrictionComesFromTheVelocityRelativeToTheSurface) {
  const ForceModelParams params = default_force_model_params();
  const ContactForceParams& heart = params.of(TissueKind::heart);
  // The wall slides along +x at 30 mm/s under a device moving with it: no tangential force.
  const LocalModel m = one_contact(Vec3(0.03, 0, 0));
  DeviceTip tip;
  tip.position = Vec3(0, 0, 0.008);
  tip.velocity = Vec3(0.03, 0, 0);
  EXPECT_NEAR(evaluate_local_model(m, params, tip, 1.0).tangential.norm(), 0, 1e-15);
  // A still device on that wall feels friction along +x (against its motion relative to the
  // wall, which is -x): mu F_n + k_c 0.03.
  tip.velocity.setZero();
  const ForceChannels f = evaluate_local_model(m, params, tip, 1.0);
  const Real f_n = heart.stiffness * 0.002;
  EXPECT_NEAR(f.tangential.x(), heart.friction * f_n + heart.cutting_resistance * 0.03, 1e-12);
}

TEST(LocalModel, ChannelsOfSeveralContactsAreSummedThenClamped) {
  const ForceModelParams params = default_force_model_params();
  LocalModel m = one_contact(Vec3::Zero());
  m.contacts[1] = m.contacts[0];
  m.contact_count = 2;
  DeviceTip tip;
  tip.position = Vec3(0, 0, 0.01 - 0.004);  // 4 mm deep: 1.6 N each on the heart
  EXPECT_NEAR(evaluate_local_model(m, params, tip, 1.0).normal_n,
              2 * params.of(TissueKind::heart).stiffness * 0.004, 1e-12);
  tip.position.z() = 0.01 - 0.010;  // 10 mm: 4 N each, 8 N summed, clamped to eq. 17's 5 N
  EXPECT_NEAR(evaluate_local_model(m, params, tip, 1.0).normal_n, kMaxNormalForce, 1e-12);
  m.contact_count = 99;  // a corrupt count reads only the contacts there are
  EXPECT_LE(evaluate_local_model(m, params, tip, 1.0).normal_n, kMaxNormalForce);
}

TEST(LocalModel, TheCauteryAddsItsThermalTermOnlyInContact) {
  const ForceModelParams params = default_force_model_params();
  LocalModel m = one_contact(Vec3::Zero());
  m.contacts[0].tissue = TissueKind::fascia;
  m.cautery = CauteryMode::cut;
  m.power_w = 40;
  DeviceTip tip;
  tip.position = Vec3(0, 0, 0.009);  // 1 mm deep
  const ThermalForceParams& t = *params.thermal_of(TissueKind::fascia, CauteryMode::cut);
  EXPECT_NEAR(evaluate_local_model(m, params, tip, 1.0).thermal_n,
              t.coefficient * 40 * std::exp(-t.decay * 0.001), 1e-12);
  tip.position.z() = 0.011;  // 1 mm above the surface
  EXPECT_EQ(evaluate_local_model(m, params, tip, 1.0).total(), Vec3::Zero());
}

}  // namespace
}  // namespace imasim::haptics
