// Damping (eq. 4) as the paper's engine reads it (SPEC S1): k_l and k_c are shares removed per
// 5 ms, whatever the particles' masses, the substep count and the step.
#include <gtest/gtest.h>

#include "precision.hpp"

#include <cmath>

#include "physics/damping.hpp"
#include "physics/executor.hpp"
#include "physics/step.hpp"

namespace imasim::physics {
namespace {

Model weightless_model(double linear, double angular, std::uint32_t substeps = 1) {
  Model model;
  ObjectParams body;
  body.gravity.setZero();
  body.linear_damping = linear;
  body.angular_damping = angular;
  model.objects.push_back(body);
  model.solver.substeps = substeps;
  return model;
}

// A free particle keeps (1 - k_l) of its velocity per 5 ms: the same for a milligram and a
// kilogram, for 1 and 16 substeps, and for a 2.5 ms step (two steps per 5 ms).
TEST(Damping, LinearRemovesTheShareKlPer5msWhateverMassAndSubsteps) {
  const double kl = 0.03;
  for (const double mass : {1e-6, 1.0}) {
    for (const std::uint32_t substeps : {1u, 16u}) {
      for (const double dt : {0.005, 0.0025}) {
        Model model = weightless_model(kl, 0, substeps);
        model.solver.dt = dt;
        State state;
        state.particles.add(Vec3::Zero(), mass, 0);
        const Vec3 v0(1, -2, 0.5);
        state.particles.velocity[0] = v0;
        Executor exec(1);
        const int steps = int(std::lround(0.1 / dt));  // 100 ms: 20 shares of 5 ms
        for (int n = 0; n < steps; ++n)
          ASSERT_TRUE(step(model, state, exec).ok());
        const Vec3 expected = v0 * std::pow(1 - kl, 20);
        // Positions grow to 0.1 m, so v = (p - x)/h rounds at 1e-16 x 0.1 / h per substep.
        EXPECT_LT((state.particles.velocity[0] - expected).norm(), 1e-9)
            << "mass " << mass << " substeps " << substeps << " dt " << dt;
      }
    }
  }
}

TEST(Damping, KeepFactorComposesOverSubsteps) {
  EXPECT_DOUBLE_EQ(damping_keep(0.03, 0.005), 0.97);
  EXPECT_NEAR(std::pow(damping_keep(0.03, 0.005 / 32), 32), 0.97, 1e-15);
  EXPECT_DOUBLE_EQ(damping_keep(0, 0.001), 1.0);
}

struct Ring {
  Model model;
  State state;
};

// Eight particles of 0.25 kg on a circle of radius 0.1 m in the x-y plane around centre c,
// spinning at omega about z and drifting with velocity u; `wobble` adds a radial breathing
// velocity (a deformation) of that speed.
Ring make_ring(double angular, const Vec3& c, double omega, const Vec3& u, double wobble = 0,
               std::uint32_t substeps = 1) {
  Ring r{weightless_model(0, angular, substeps), {}};
  for (int k = 0; k < 8; ++k) {
    const double a = 2 * 3.14159265358979 * k / 8;
    const Vec3 rel(0.1 * std::cos(a), 0.1 * std::sin(a), 0);
    const std::uint32_t i = r.state.particles.add(c + rel, 0.25, 0);
    r.state.particles.velocity[i] = u + Vec3(0, 0, omega).cross(rel) + wobble * rel / 0.1;
  }
  return r;
}

double angular_momentum_z(const State& s, const Vec3& c) {
  double lz = 0;
  for (std::size_t i = 0; i < s.particles.size(); ++i)
    lz += 0.25 * (s.particles.position[i] - c).cross(s.particles.velocity[i]).z();
  return lz;
}

// Mueller's damping keeps rigid motion: a spinning, drifting ring with k_c = 1 (everything
// non-rigid removed at once) keeps its spin and its drift exactly.
TEST(Damping, AngularNeverSlowsARigidMotion) {
  const Vec3 c(0.1, 0.2, 0.3), drift(0.3, 0, -0.1);
  Ring ring = make_ring(1, c, 3, drift);
  Executor exec(1);
  const double lz0 = angular_momentum_z(ring.state, c);
  ASSERT_TRUE(step(ring.model, ring.state, exec).ok());
  // The centre moved with the drift; about it L_z is unchanged (no constraint, no damping of it).
  const Vec3 centre = c + 0.005 * drift;
  EXPECT_NEAR(angular_momentum_z(ring.state, centre), lz0, 1e-12);
  Vec3 momentum = Vec3::Zero();
  for (const Vec3& v : ring.state.particles.velocity)
    momentum += 0.25 * v;
  EXPECT_LT((momentum - 2 * drift).norm(), 1e-12);
}

// It damps the deviation from rigid motion by the share k_c per 5 ms, whatever the substeps.
TEST(Damping, AngularRemovesTheShareKcOfTheDeformationPer5ms) {
  const double kc = 0.2, wobble = 0.05;
  for (const std::uint32_t substeps : {1u, 8u}) {
    Ring ring = make_ring(kc, Vec3::Zero(), 0, Vec3::Zero(), wobble, substeps);
    Executor exec(1);
    ASSERT_TRUE(step(ring.model, ring.state, exec).ok());
    for (std::size_t i = 0; i < 8; ++i) {
      const Vec3 radial = ring.state.particles.position[i].normalized();
      // The ring breathes outwards (no constraint): the radial speed after one 5 ms step.
      EXPECT_NEAR(ring.state.particles.velocity[i].dot(radial), wobble * (1 - kc), 1e-12)
          << "substeps " << substeps;
    }
  }
}

}  // namespace
}  // namespace imasim::physics
