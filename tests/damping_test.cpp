// Damping (eq. 4) against its implicit-Euler closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/executor.hpp"
#include "physics/step.hpp"

namespace imasim::physics {
namespace {

Model weightless_model(double linear, double angular) {
  Model model;
  ObjectParams body;
  body.gravity.setZero();
  body.linear_damping = linear;
  body.angular_damping = angular;
  model.objects.push_back(body);
  return model;
}

TEST(Damping, LinearDecaysByTheImplicitFactorEachStep) {
  const double kl = 0.2, mass = 0.5;  // kg/s, kg
  Model model = weightless_model(kl, 0);
  State state;
  state.particles.add(Vec3::Zero(), mass, 0);
  state.particles.velocity[0] = Vec3(1, -2, 0.5);
  Executor exec(1);
  const double factor = 1 / (1 + kl / mass * model.solver.dt);
  for (int n = 1; n <= 50; ++n) {
    ASSERT_TRUE(step(model, state, exec).ok());
    const Vec3 expected = Vec3(1, -2, 0.5) * std::pow(factor, n);
    EXPECT_LT((state.particles.velocity[0] - expected).norm(), 1e-13);
  }
}

struct Ring {
  Model model;
  State state;
};

// Eight particles on a circle in the x-y plane around centre c, spinning at omega about z and
// drifting with velocity u.
Ring make_ring(double angular, const Vec3& c, double omega, const Vec3& u) {
  Ring r{weightless_model(0, angular), {}};
  for (int k = 0; k < 8; ++k) {
    const double a = 2 * 3.14159265358979 * k / 8;
    const Vec3 rel(0.1 * std::cos(a), 0.1 * std::sin(a), 0);
    const std::uint32_t i = r.state.particles.add(c + rel, 0.25, 0);
    r.state.particles.velocity[i] = u + Vec3(0, 0, omega).cross(rel);
  }
  return r;
}

Vec3 momentum(const State& s) {
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < s.particles.size(); ++i)
    p += s.particles.velocity[i] / s.particles.inverse_mass[i];
  return p;
}

TEST(Damping, AngularSlowsTheRigidRotationByTheClosedFormFactor) {
  const double kc = 1, omega = 3;  // kg m^2/s, rad/s
  const Vec3 drift(0.3, 0, -0.1);
  Ring ring = make_ring(kc, Vec3(1, 2, 3), omega, drift);
  Executor exec(1);
  const Vec3 p0 = momentum(ring.state);
  ASSERT_TRUE(step(ring.model, ring.state, exec).ok());
  // After the position update each particle sits at r1 = r0 + (omega x r0) h about the centre,
  // so L_z = sum m r1 x v0 = sum m r0 x v0 = I0 omega with I0 = sum m |r0|^2 = 8 * 0.25 * 0.1^2,
  // and the implicit damping gives (I1 + k h) omega' = L_z with I1 = sum m |r1|^2.
  const Particles& P = ring.state.particles;
  Vec3 centre = Vec3::Zero();
  for (std::size_t i = 0; i < P.size(); ++i)
    centre += P.position[i] / 8;
  double izz = 0, lz = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    const Vec3 r = P.position[i] - centre;
    izz += 0.25 * r.squaredNorm();
    lz += 0.25 * r.cross(P.velocity[i]).z();
  }
  const double h = ring.model.solver.dt;
  const double expected_omega = omega * 0.02 / (izz + kc * h);
  EXPECT_NEAR(lz / izz, expected_omega, 1e-12);
  EXPECT_LT(expected_omega, omega * 0.99);  // the test would notice no damping
  // Linear momentum untouched, to the rounding of positions about 3.7 m from the origin.
  EXPECT_LT((momentum(ring.state) - p0).norm(), 1e-12);
}

TEST(Damping, AngularLeavesAPureTranslationAlone) {
  Ring ring = make_ring(0.01, Vec3::Zero(), 0, Vec3(0.2, -0.4, 0.1));
  Executor exec(1);
  ASSERT_TRUE(step(ring.model, ring.state, exec).ok());
  for (const Vec3& v : ring.state.particles.velocity) {
    EXPECT_LT((v - Vec3(0.2, -0.4, 0.1)).norm(), 1e-14);
  }
}

}  // namespace
}  // namespace imasim::physics
