// Friction on the implicit membrane's contacts (physics/implicit_membrane.hpp): smoothed Coulomb
// friction against a vertex's slip over the step, pressed by a lagged normal force. Checked
// against its closed forms: the potential's slopes by finite differences, the creep of a vertex
// under less than its bound, the slide at Coulomb's force past it, a tool's plane carrying what
// it presses.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "physics/implicit_membrane.hpp"

namespace imasim::physics {
namespace {

const Vec3 kGravity(0, -9.81, 0);

TEST(FrictionPotential, ItsSlopesAreItsEnergysAndCoulombsBoundFromTheStickSlipDistanceOn) {
  const double mu_lambda = 0.03, eps = 1e-6, d = 1e-12;
  for (double s : {1e-9, 2e-7, 5e-7, 9e-7, 1.5e-6, 4e-5}) {
    const FrictionTerms at = friction_potential(mu_lambda, s, eps);
    const FrictionTerms up = friction_potential(mu_lambda, s + d, eps);
    const FrictionTerms down = friction_potential(mu_lambda, s - d, eps);
    // The force's size per_slip s is dE/ds; along_slip is its own slope.
    EXPECT_NEAR(at.per_slip * s, (up.energy - down.energy) / (2 * d), 1e-6 * mu_lambda) << s;
    EXPECT_NEAR(at.along_slip, (up.per_slip * (s + d) - down.per_slip * (s - d)) / (2 * d),
                1e-4 * mu_lambda / eps)
        << s;
    EXPECT_GE(at.along_slip, 0);
    EXPECT_LE(at.per_slip * s, mu_lambda * (1 + 1e-12));  // never more than Coulomb's bound
    if (s >= eps) {
      EXPECT_DOUBLE_EQ(at.per_slip * s, mu_lambda);
    }
  }
  // Continuous at eps: the energy, and the force reaching the bound.
  const FrictionTerms below = friction_potential(mu_lambda, eps * (1 - 1e-12), eps);
  EXPECT_NEAR(below.energy, mu_lambda * eps, 1e-11 * mu_lambda * eps);
  EXPECT_NEAR(below.per_slip * eps, mu_lambda, 1e-11 * mu_lambda);
  EXPECT_DOUBLE_EQ(friction_potential(mu_lambda, 0, eps).per_slip, 2 * mu_lambda / eps);
}

// A 1 g vertex resting on a fixed floor (held on it), pressed by its weight, pushed along the
// floor by a steady force F.
struct Pushed {
  double per_step = 0;  // its slip over the last step (unit: m)
  double speed = 0;     // along the push (unit: m/s)
  double friction = 0;  // the floor's friction on it, along the push (unit: N)
};

Pushed push_along_floor(double mu, double push, int steps, const ImplicitSolveParams& solve) {
  const double m = 0.001;
  ImplicitMembrane point({m}, {0}, {}, 0.005);
  std::vector<Vec3> x = {Vec3::Zero()}, v = {Vec3::Zero()};
  const std::vector<Vec3> force = {Vec3(push, 0, 0)};
  std::vector<MembraneContact> floor = {{0, Vec3::Zero(), Vec3::UnitY()}};
  floor[0].friction = mu;
  floor[0].normal_force = m * 9.81;  // lagged: the weight it rests with
  Pushed out;
  for (int step = 0; step < steps; ++step) {
    const double before = x[0].x();
    const ImplicitStepReport r = point.step(x, v, {kGravity, force, floor, {}}, solve);
    EXPECT_TRUE(r.ok);
    EXPECT_LT(r.residual, solve.tolerance) << "step " << step;
    out.per_step = x[0].x() - before;
  }
  EXPECT_EQ(x[0].y(), 0);  // held on the floor throughout
  out.speed = v[0].x();
  out.friction = point.contact_frictions()[0].x();
  return out;
}

TEST(MembraneFriction, AVertexPushedWithHalfItsBoundCreepsAsTheSmoothedLawSays) {
  const ImplicitSolveParams solve;
  const double mu = 0.4, bound = mu * 0.001 * 9.81;
  const Pushed held = push_along_floor(mu, 0.5 * bound, 200, solve);
  // Steady: the friction balances the push, f0'(s) = F / (mu lambda), so the slip a step is
  // eps (1 - sqrt(1 - F / (mu lambda))) = 0.293 eps.
  EXPECT_NEAR(held.per_step, solve.stick_slip * (1 - std::sqrt(0.5)), 1e-4 * solve.stick_slip);
  EXPECT_NEAR(held.friction, -0.5 * bound, solve.tolerance);  // balanced to Newton's tolerance
  // Without friction the same push accelerates it: F / m t^2 / 2 = 2.45 mm after 1 s.
  const Pushed free = push_along_floor(0, 0.5 * bound, 200, solve);
  EXPECT_GT(free.speed, 0.5 * bound / 0.001 * 0.9);
}

TEST(MembraneFriction, AVertexPushedPastItsBoundSlidesAgainstCoulombsForce) {
  const ImplicitSolveParams solve;
  const double mu = 0.4, bound = mu * 0.001 * 9.81;
  const Pushed sliding = push_along_floor(mu, 2 * bound, 100, solve);
  // Backward Euler under the constant net force F - mu lambda: v = n h (F - mu lambda) / m.
  EXPECT_NEAR(sliding.speed, 100 * 0.005 * bound / 0.001, 1e-9);
  EXPECT_NEAR(sliding.friction, -bound, 1e-12);
}

// A tool's plane (on a proxy body pulled along by its device at 10 mm/s) under a 1 g vertex
// pressed onto it by its weight: with friction the vertex travels with the tool; without, the
// plane slides away under it. The body feels the friction it takes the vertex along with.
TEST(MembraneFriction, AToolsPlaneMovingAlongCarriesTheVertexItPresses) {
  for (const double mu : {0.0, 0.5}) {
    const double m = 0.001, h = 0.005, speed = 0.01;
    ImplicitMembrane point({m}, {0}, {}, h, {}, 1);
    std::vector<Vec3> x = {Vec3::Zero()}, v = {Vec3::Zero()};
    std::vector<MembraneBody> body = {{Vec3::Zero(), 1000, 0, Vec3::Zero()}};
    const ImplicitSolveParams solve;
    for (int step = 0; step < 200; ++step) {
      body[0].anchor = Vec3(speed * h * (step + 1), 0, 0);
      // The plane where the body's start puts it; the contact's surface moves with the body.
      std::vector<MembraneContact> top = {{0, body[0].position, Vec3::UnitY(), 0}};
      top[0].friction = mu;
      top[0].normal_force = m * 9.81;
      const ImplicitStepReport r = point.step(x, v, {kGravity, {}, top, body}, solve);
      ASSERT_TRUE(r.ok);
      EXPECT_LT(r.residual, solve.tolerance) << "step " << step;
    }
    const double travelled = body[0].position.x();
    EXPECT_NEAR(travelled, 0.01, 1e-5);  // 1 s at 10 mm/s
    if (mu > 0) {
      // Carried: it slipped only while the tool set it going (0.23 eps in the first step).
      EXPECT_NEAR(x[0].x(), travelled, 2 * solve.stick_slip) << "mu " << mu;
      EXPECT_NEAR(v[0].x(), speed, 1e-3 * speed);
    } else {
      EXPECT_NEAR(x[0].x(), 0, 1e-12);
    }
  }
}

// A fixed surface that moves along itself (the heart's wall sliding under the fascia): the
// contact's `motion` is the surface's own over the step, and friction carries the 1 g vertex on it
// with it; a contact that leaves its motion out holds the vertex back instead.
TEST(MembraneFriction, AFixedSurfaceSlidingAlongItselfCarriesTheVertexOnIt) {
  const double m = 0.001, h = 0.005, speed = 0.01;
  const ImplicitSolveParams solve;
  for (const bool moving : {true, false}) {
    ImplicitMembrane point({m}, {0}, {}, h);
    std::vector<Vec3> x = {Vec3::Zero()}, v = {Vec3::Zero()};
    std::vector<MembraneContact> floor = {{0, Vec3::Zero(), Vec3::UnitY()}};
    floor[0].friction = 0.5;
    floor[0].normal_force = m * 9.81;
    floor[0].motion = moving ? Vec3(speed * h, 0, 0) : Vec3::Zero();
    for (int step = 0; step < 200; ++step) {
      const ImplicitStepReport r = point.step(x, v, {kGravity, {}, floor, {}}, solve);
      ASSERT_TRUE(r.ok);
      EXPECT_LT(r.residual, solve.tolerance) << "step " << step;
    }
    if (moving) {
      // Carried: it slipped only while the surface set it going (10 mm/s in one step is 0.4 of
      // its bound: 0.23 eps).
      EXPECT_NEAR(x[0].x(), 200 * speed * h, 2 * solve.stick_slip);
      EXPECT_NEAR(v[0].x(), speed, 1e-3 * speed);
    } else {
      EXPECT_EQ(x[0].x(), 0);
    }
  }
}

TEST(MembraneFriction, AContactWithNegativeFrictionOrNormalForceIsRefused) {
  ImplicitMembrane point({0.001}, {0}, {}, 0.005);
  std::vector<Vec3> x = {Vec3::Zero()}, v = {Vec3::Zero()};
  std::vector<MembraneContact> floor = {{0, Vec3::Zero(), Vec3::UnitY()}};
  floor[0].friction = -0.1;
  floor[0].normal_force = 0.01;
  EXPECT_THROW(point.step(x, v, {kGravity, {}, floor, {}}, {}), std::invalid_argument);
  floor[0].friction = 0.1;
  floor[0].normal_force = -0.01;
  EXPECT_THROW(point.step(x, v, {kGravity, {}, floor, {}}, {}), std::invalid_argument);
  floor[0].normal_force = 0.01;
  ImplicitSolveParams no_slip;
  no_slip.stick_slip = 0;
  EXPECT_THROW(point.step(x, v, {kGravity, {}, floor, {}}, no_slip), std::invalid_argument);
}

}  // namespace
}  // namespace imasim::physics
