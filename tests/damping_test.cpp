// Damping (eq. 4) against its implicit-Euler closed form.
#include <gtest/gtest.h>

#include "precision.hpp"

#include <cmath>

#include "physics/damping.hpp"
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
    // v = (p - x)/h rounds at the scale of |x| ~ k h |v| in step k: at most sum_k (k + 1) units
    // of |v| in all, far below the (k_l w h)^2 per step that an explicit update would change.
    EXPECT_LT((state.particles.velocity[0] - expected).norm(),
              test::ulps(n * (n + 1) / 2.0 + n, 2.5));
  }
}

struct Ring {
  Model model;
  State state;
};

// Eight particles of 0.25 kg on a circle of radius 0.1 m in the x-y plane around centre c,
// spinning at omega about z and drifting with velocity u.
Ring make_ring(double angular, const Vec3& c, double omega, const Vec3& u) {
  Ring r{weightless_model(0, angular), {}};
  for (int k = 0; k < 8; ++k) {
    const double a = 2 * 3.14159265358979 * k / 8;
    const Vec3 rel(0.1 * std::cos(a), 0.1 * std::sin(a), 0);
    const std::uint32_t i = r.state.particles.add(c + rel, 0.25, 0);
    r.state.particles.velocity[i] = u + Vec3(0, 0, omega).cross(rel);
  }
  prepare_state(r.model, r.state);
  return r;
}

Vec3 momentum(const State& s) {
  Vec3 p = Vec3::Zero();
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    p += s.particles.velocity[i] / s.particles.inverse_mass[i];
  }
  return p;
}

// The damping pass itself, on known positions and velocities.
TEST(Damping, AngularSlowsTheRigidRotationByTheClosedFormFactor) {
  const double kc = 1, omega = 3, h = 0.005;  // kg m^2/s, rad/s, s
  const Vec3 drift(0.3, 0, -0.1);
  Ring ring = make_ring(kc, Vec3(0.1, 0.2, 0.3), omega, drift);
  const Vec3 p0 = momentum(ring.state);
  apply_angular_damping(ring.model, ring.state, h);
  // I_zz = 8 * 0.25 * 0.1^2 = 0.02 kg m^2, and (I + k h) omega' = I omega.
  const double expected_omega = omega * 0.02 / (0.02 + kc * h);
  for (std::size_t i = 0; i < 8; ++i) {
    const Vec3 r = ring.state.particles.position[i] - Vec3(0.1, 0.2, 0.3);
    const Vec3 expected = drift + Vec3(0, 0, expected_omega).cross(r);
    EXPECT_LT((ring.state.particles.velocity[i] - expected).norm(), test::ulps(16, 1));
  }
  EXPECT_LT((momentum(ring.state) - p0).norm(), test::ulps(16, 1));  // linear momentum kept
}

TEST(Damping, AngularLeavesAPureTranslationAlone) {
  Ring ring = make_ring(0.01, Vec3::Zero(), 0, Vec3(0.2, -0.4, 0.1));
  apply_angular_damping(ring.model, ring.state, 0.005);
  for (const Vec3& v : ring.state.particles.velocity) {
    EXPECT_LT((v - Vec3(0.2, -0.4, 0.1)).norm(), test::ulps(4, 0.5));
  }
}

TEST(Damping, AngularDampingRunsInsideTheStep) {
  Ring ring = make_ring(1, Vec3::Zero(), 3, Vec3::Zero());
  Executor exec(1);
  ASSERT_TRUE(step(ring.model, ring.state, exec).ok());
  double lz = 0;
  for (std::size_t i = 0; i < 8; ++i) {
    lz += 0.25 * ring.state.particles.position[i].cross(ring.state.particles.velocity[i]).z();
  }
  // Undamped, L_z = I omega = 0.06 is conserved; damped by (I + k h) it drops by about 20 %.
  EXPECT_LT(lz, 0.9 * 0.02 * 3);
}

}  // namespace
}  // namespace imasim::physics
