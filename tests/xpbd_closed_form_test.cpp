// The solver against closed-form answers: free fall, a particle hanging on one compliant
// distance constraint (XPBD stretch = m g alpha), PBD's rigid projection, XPBD's
// iteration-independent equilibrium.
#include <gtest/gtest.h>

#include "precision.hpp"

#include <cmath>

#include "physics/constraint_system.hpp"
#include "physics/executor.hpp"
#include "physics/step.hpp"

namespace imasim::physics {
namespace {

constexpr double kG = 9.81;

struct Pendulum {
  Model model;
  State state;
};

// Particle 0 fixed at the origin, particle 1 of mass m hanging 1 m below on one constraint.
Pendulum make_hanging_particle(double mass, const ConstraintMaterial& material,
                               double linear_damping, std::uint32_t iterations) {
  Pendulum p;
  p.model.solver.iterations = iterations;
  ObjectParams body;
  body.linear_damping = linear_damping;
  p.model.objects.push_back(body);
  const MaterialId id = p.model.add_material(material);
  p.state.particles.add(Vec3(0, 0, 0), 1, 0);
  p.state.particles.fix(0);
  p.state.particles.add(Vec3(0, -1, 0), mass, 0);
  add_distance(p.state.constraints, p.state.particles, 0, 1, id);
  prepare_state(p.model, p.state);
  return p;
}

TEST(ClosedForm, FreeFallFollowsTheSymplecticPrediction) {
  Model model;
  model.objects.push_back({});
  State state;
  state.particles.add(Vec3(0, 2, 0), 0.1, 0);
  Executor exec(1);
  const double h = model.solver.dt;
  for (int n = 1; n <= 200; ++n) {
    ASSERT_TRUE(step(model, state, exec).ok());
    // v_n = -g h n (mean velocity over step n), y_n = y_0 - g h^2 n (n + 1) / 2.
    // Worst-case rounding: each step's v = (p - x)/h adds at most one rounding of positions near
    // 2 m divided by h, and the position sums those velocity errors. Both bounds stay far below
    // what eq. 1 taken literally (x + v h + g h^2 / 2) would change: g h n / 2 in v.
    EXPECT_NEAR(state.particles.velocity[0].y(), -kG * h * n, test::ulps(n, 2) / h);
    EXPECT_NEAR(state.particles.position[0].y(), 2 - kG * h * h * n * (n + 1) / 2,
                test::ulps(n * (n + 1) / 2.0 + n, 2));
  }
  EXPECT_NEAR(state.time, 200 * h, 1e-12);  // time is kept in double
}

TEST(ClosedForm, XpbdHangingParticleStretchesByMassTimesGravityTimesCompliance) {
  for (const double alpha : {1e-4, 1e-3, 1e-2}) {
    const double mass = 0.1;
    Pendulum p = make_hanging_particle(mass, ConstraintMaterial::xpbd(alpha), 0.5, 5);
    Executor exec(1);
    for (int n = 0; n < 4000; ++n)
      ASSERT_TRUE(step(p.model, p.state, exec).ok());
    const double stretch =
        (p.state.particles.position[1] - p.state.particles.position[0]).norm() - 1;
    // Exact at the fixed point, up to the rounding of positions near 1 m (a stretch is a small
    // difference of two such lengths) as it settles into the fixed point: 16 units of it,
    // 2 % of the smallest stretch here.
    EXPECT_NEAR(stretch, mass * kG * alpha, test::ulps(16, 1)) << "alpha " << alpha;
    EXPECT_LT(p.state.particles.velocity[1].norm(), test::ulps(4, 1) / p.model.solver.dt);
  }
}

TEST(ClosedForm, XpbdEquilibriumDoesNotDependOnIterationCount) {
  const double alpha = 1e-3, mass = 0.2;
  double stretch[2];
  int k = 0;
  for (const std::uint32_t iterations : {1u, 25u}) {
    Pendulum p = make_hanging_particle(mass, ConstraintMaterial::xpbd(alpha), 1.0, iterations);
    Executor exec(1);
    for (int n = 0; n < 4000; ++n)
      ASSERT_TRUE(step(p.model, p.state, exec).ok());
    stretch[k++] = (p.state.particles.position[1] - p.state.particles.position[0]).norm() - 1;
  }
  EXPECT_NEAR(stretch[0], stretch[1], test::ulps(16, 1));
  EXPECT_NEAR(stretch[0], mass * kG * alpha, test::ulps(16, 1));
}

TEST(ClosedForm, PbdStiffnessOneHoldsTheLengthExactly) {
  Pendulum p = make_hanging_particle(0.1, ConstraintMaterial::pbd(1), 0, 1);
  Executor exec(1);
  for (int n = 0; n < 100; ++n) {
    ASSERT_TRUE(step(p.model, p.state, exec).ok());
    EXPECT_NEAR((p.state.particles.position[1] - p.state.particles.position[0]).norm(), 1,
                test::ulps(2, 1));
  }
}

TEST(ClosedForm, PbdStiffnessScalesOneProjection) {
  // One projection removes the fraction k of the error: C' = (1 - k) C.
  for (const double k : {0.0, 0.25, 1.0}) {
    std::array<Vec3, 2> x = {Vec3(0, 0, 0), Vec3(0, -1.2, 0)};
    const std::array<Real, 2> w = {0, 10};
    const ProjectionTerms terms = projection_terms(ConstraintMaterial::pbd(k), 0.005);
    DistanceRow row;
    row.i = 0;
    row.j = 1;
    row.rest_length = 1;
    Real lambda = 0;
    project_distance(row, lambda, {x.data(), w.data(), &terms});
    EXPECT_NEAR((x[1] - x[0]).norm() - 1, (1 - k) * 0.2, test::ulps(4, 1.2)) << "k " << k;
  }
}

}  // namespace
}  // namespace imasim::physics

namespace imasim::physics {
namespace {

// An attachment (three linear rows) of compliance alpha holds a particle under gravity at
// target - m g alpha, exactly, from the first substep on (the rows are independent and one
// projection solves them); a particle on its target feels no correction (no singular gradient).
TEST(ClosedForm, AttachmentHangsByMGAlphaAndRestsOnItsTarget) {
  Model model;
  model.objects.push_back(ObjectParams{});
  model.solver.substeps = 4;
  model.solver.iterations = 1;
  const double alpha = 1e-3, mass = 0.02;  // m/N, kg
  const MaterialId id = model.add_material(ConstraintMaterial::xpbd(alpha));
  State state;
  state.particles.add(Vec3(0, -mass * 9.81 * alpha, 0), mass, 0);
  state.particles.add(Vec3(1, 0, 0), mass, 0);
  add_attachment(state.constraints, state.particles, 0, Vec3::Zero(), id);
  model.objects.push_back(ObjectParams{});
  model.objects[1].gravity.setZero();
  state.particles.object[1] = 1;
  add_attachment(state.constraints, state.particles, 1, Vec3(1, 0, 0), id);
  Executor exec(1);
  for (int n = 0; n < 50; ++n) {
    ASSERT_TRUE(step(model, state, exec).ok());
    EXPECT_NEAR(state.particles.position[0].y(), -mass * 9.81 * alpha, 1e-15);
    EXPECT_NEAR(state.particles.velocity[0].norm(), 0, 1e-12);
    EXPECT_EQ(state.particles.position[1], Vec3(1, 0, 0));
    EXPECT_TRUE(state.particles.velocity[1].allFinite());
  }
}

}  // namespace
}  // namespace imasim::physics
