// eq. 17-19 at every branch, against values computed by hand.
#include <gtest/gtest.h>

#include <cmath>

#include "haptics/force_law.hpp"
#include "haptics/force_params.hpp"

namespace imasim::haptics {
namespace {

const ContactForceParams kTissue{300, 2, 0.2, 5};  // k_d N/m, c_d N s/m, mu, k_c N s/m
const ThermalForceParams kThermal{0.004, 1000};    // k_t N/W, alpha 1/m

ContactKinematics pressing(Real depth, const Vec3& velocity) {
  ContactKinematics c;
  c.depth = depth;
  c.normal = Vec3::UnitZ();
  c.relative_velocity = velocity;
  return c;
}

TEST(ForceLaw, NormalChannelIsStiffnessTimesDepthPlusDamping) {
  // 4 mm deep, pressing in at 10 mm/s: F_n = 300 * 0.004 + 2 * 0.01 = 1.22 N, along +z.
  const ForceChannels f = contact_force(kTissue, nullptr, 0, pressing(0.004, Vec3(0, 0, -0.01)));
  EXPECT_NEAR(f.normal_n, 1.22, 1e-12);
  EXPECT_TRUE(f.normal.isApprox(Vec3(0, 0, 1.22), 1e-12));
  // At rest, no sliding: F_t is the friction of F_n alone (0.2 * 1.2 N), but with no sliding
  // direction its vector fades to zero.
  const ForceChannels still = contact_force(kTissue, nullptr, 0, pressing(0.004, Vec3::Zero()));
  EXPECT_NEAR(still.normal_n, 1.2, 1e-12);
  EXPECT_NEAR(still.tangential_n, 0.24, 1e-12);
  EXPECT_EQ(still.tangential, Vec3::Zero());
}

TEST(ForceLaw, NormalChannelIsClampedToZeroAndFiveNewtons) {
  // 30 mm deep: 9 N by eq. 17, clamped to 5 N.
  EXPECT_EQ(contact_force(kTissue, nullptr, 0, pressing(0.03, Vec3::Zero())).normal_n, 5);
  // 1 mm deep but pulling out at 0.5 m/s: 0.3 - 1.0 < 0, clamped to 0 (tissue does not pull).
  const ForceChannels out = contact_force(kTissue, nullptr, 0, pressing(0.001, Vec3(0, 0, 0.5)));
  EXPECT_EQ(out.normal_n, 0);
  EXPECT_EQ(out.normal, Vec3::Zero());
}

TEST(ForceLaw, TangentialChannelOpposesSlidingAndIsClampedToTwoNewtons) {
  // 4 mm deep (F_n = 1.2 N), sliding along +x at 0.1 m/s: F_t = 0.2 * 1.2 + 5 * 0.1 = 0.74 N
  // along -x.
  const ForceChannels f = contact_force(kTissue, nullptr, 0, pressing(0.004, Vec3(0.1, 0, 0)));
  EXPECT_NEAR(f.tangential_n, 0.74, 1e-12);
  EXPECT_TRUE(f.tangential.isApprox(Vec3(-0.74, 0, 0), 1e-12));
  EXPECT_NEAR(f.normal_n, 1.2, 1e-12);  // sliding does not change the normal channel
  // At 1 m/s: 0.24 + 5 = 5.24 N, clamped to 2 N.
  const ForceChannels fast = contact_force(kTissue, nullptr, 0, pressing(0.004, Vec3(0, 1, 0)));
  EXPECT_EQ(fast.tangential_n, 2);
  EXPECT_TRUE(fast.tangential.isApprox(Vec3(0, -2, 0), 1e-12));
  // Sliding slower than the regularisation speed: the vector scales with the speed.
  const ForceChannels slow =
      contact_force(kTissue, nullptr, 0, pressing(0.004, Vec3(0.5 * kSlidingSpeedScale, 0, 0)));
  EXPECT_NEAR(slow.tangential.x(), -0.5 * slow.tangential_n, 1e-12);
}

TEST(ForceLaw, ThermalChannelOnlyWhileTheCauteryIsActive) {
  const ContactKinematics c = pressing(0.002, Vec3::Zero());
  // 40 W, 2 mm: k_t P exp(-alpha d) = 0.004 * 40 * exp(-2) = 0.021654 N along the normal.
  const ForceChannels on = contact_force(kTissue, &kThermal, 40, c);
  EXPECT_NEAR(on.thermal_n, 0.16 * std::exp(-2.0), 1e-12);
  EXPECT_TRUE(on.thermal.isApprox(Vec3(0, 0, 0.16 * std::exp(-2.0)), 1e-12));
  EXPECT_EQ(contact_force(kTissue, nullptr, 40, c).thermal_n, 0);   // cautery off
  EXPECT_EQ(contact_force(kTissue, &kThermal, 0, c).thermal_n, 0);  // no power
  EXPECT_TRUE(on.total().isApprox(on.normal + on.tangential + on.thermal));
}

TEST(ForceLaw, OutOfContactEveryChannelIsZero) {
  for (const Real depth : {Real(0), Real(-0.001), Real(NAN)}) {
    const ForceChannels f = contact_force(kTissue, &kThermal, 40, pressing(depth, Vec3(1, 1, -1)));
    EXPECT_EQ(f.total(), Vec3::Zero()) << depth;
    EXPECT_EQ(f.normal_n + f.tangential_n + f.thermal_n, 0) << depth;
  }
}

TEST(ForceLaw, TheNormalNeedNotBeAnAxis) {
  // The same contact turned: the channels turn with it.
  const Vec3 n = Vec3(1, 2, 2) / 3;
  ContactKinematics c;
  c.depth = 0.004;
  c.normal = n;
  const Vec3 slide = Vec3(2, -1, 0).normalized() * 0.1;  // perpendicular to n
  c.relative_velocity = slide - 0.01 * n;                // sliding and pressing in
  const ForceChannels f = contact_force(kTissue, nullptr, 0, c);
  EXPECT_NEAR(f.normal_n, 1.22, 1e-12);
  EXPECT_TRUE(f.normal.isApprox(1.22 * n, 1e-12));
  EXPECT_NEAR(f.tangential_n, 0.2 * 1.22 + 0.5, 1e-12);
  EXPECT_TRUE(f.tangential.isApprox(-(0.2 * 1.22 + 0.5) * slide.normalized(), 1e-12));
}

// The fascia's and the fat's k_d are the stiffness a hook's tip meets on fat: Boussinesq's rigid
// punch, 2 a E / (1 - nu^2), with the tip's a = 0.5 mm, nu = 0.5 and adipose tissue's E = 3.25 kPa
// (Samani et al. 2007); the stiffer tissues follow in order.
TEST(ForceLaw, DefaultsOrderTheTissuesAndGiveThermalOnlyInAMode) {
  const ForceModelParams p = default_force_model_params();
  const double punch = 2 * 0.0005 * 3250 / (1 - 0.5 * 0.5);  // 4.33 N/m
  EXPECT_NEAR(p.of(TissueKind::fascia).stiffness, punch, 0.01 * punch);
  EXPECT_NEAR(p.of(TissueKind::fat).stiffness, punch, 0.01 * punch);
  EXPECT_LT(p.of(TissueKind::fascia).stiffness, p.of(TissueKind::ima).stiffness);
  EXPECT_LT(p.of(TissueKind::ima).stiffness, p.of(TissueKind::heart).stiffness);
  EXPECT_LT(p.of(TissueKind::heart).stiffness, p.of(TissueKind::chest_wall).stiffness);
  EXPECT_EQ(p.thermal_of(TissueKind::fascia, CauteryMode::off), nullptr);
  ASSERT_NE(p.thermal_of(TissueKind::fascia, CauteryMode::coag), nullptr);
  EXPECT_GT(p.thermal_of(TissueKind::fascia, CauteryMode::coag)->coefficient,
            p.thermal_of(TissueKind::fascia, CauteryMode::cut)->coefficient);
  EXPECT_STREQ(tissue_kind_name(TissueKind::chest_wall), "chest_wall");
}

}  // namespace
}  // namespace imasim::haptics
