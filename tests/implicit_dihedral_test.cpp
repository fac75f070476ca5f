// The implicit membrane's bending for a surface curved at rest (MembraneDihedral,
// physics/implicit_membrane.hpp), against closed forms: a folded hinge carried round rigidly feels
// nothing, and a wing under a force turns until the hinge's moment k (theta - theta_0) balances
// the force's, F d cos(delta). The step for a tube's wall, which is curved everywhere at rest.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "physics/dihedral_constraint.hpp"
#include "physics/implicit_membrane.hpp"

namespace imasim::physics {
namespace {

StiffeningSpring stiff_spring(const Vec3& a, const Vec3& b) {
  StiffeningSpring s;
  s.rest_length = (a - b).norm();
  s.toe_stiffness = s.linear_stiffness = 1e4;  // (unit: N/m)
  s.toe_strain = 0.05;
  return s;
}

// Wings 0 and 1 on the edge (2, 3) along z, the wings at distance d from it, folded by the angle
// between them (pi: flat).
std::vector<Vec3> hinge(Real d, Real opening) {
  const Real half = Real(0.01);
  return {Vec3(d, 0, half), Vec3(d * std::cos(opening), d * std::sin(opening), half), Vec3::Zero(),
          Vec3(0, 0, 2 * half)};
}

std::vector<MembraneEdge> hinge_edges(const std::vector<Vec3>& x) {
  std::vector<MembraneEdge> edges;
  for (const auto& [i, j] : {std::pair{2u, 3u}, {0u, 2u}, {0u, 3u}, {1u, 2u}, {1u, 3u}})
    edges.push_back({i, j, stiff_spring(x[i], x[j])});
  return edges;
}

Real rest_angle_of(const std::vector<Vec3>& x) {
  return dihedral_angle(x[0], x[1], x[2], x[3]);
}

// Folded at 2 rad and carried round rigidly (a quarter turn about (1, 1, 1), moved 3 cm): one
// step leaves every vertex where it was, to rounding. The same hinge told its rest angle is 0.1
// rad more moves (so the check can fail).
TEST(ImplicitDihedral, AFoldedHingeCarriedRoundRigidlyFeelsNoBending) {
  const std::vector<Vec3> rest = hinge(0.01, 2.0);
  const Real rest_angle = rest_angle_of(rest);
  ASSERT_GT(std::abs(rest_angle), 0.5);
  const Mat3 turn = Eigen::AngleAxis<Real>(M_PI / 2, Vec3(1, 1, 1).normalized()).toRotationMatrix();
  std::vector<Vec3> moved;
  for (const Vec3& p : rest)
    moved.push_back(turn * p + Vec3(0.03, -0.01, 0.02));
  for (const Real told : {rest_angle, rest_angle + Real(0.1)}) {
    ImplicitMembrane m(std::vector<Real>(4, 1e-4), std::vector<std::uint8_t>(4, 0),
                       hinge_edges(rest), 0.005, {}, 0, {{{0, 1, 2, 3}, told, 1e-4}});
    std::vector<Vec3> x = moved, v(4, Vec3::Zero());
    const ImplicitStepReport r = m.step(x, v, {}, {});
    ASSERT_TRUE(r.ok);
    EXPECT_LT(r.residual, 1e-6);
    Real largest = 0;
    for (std::size_t k = 0; k < 4; ++k)
      largest = std::max(largest, (x[k] - moved[k]).norm());
    if (told == rest_angle)
      EXPECT_LT(largest, 1e-12);
    else
      EXPECT_GT(largest, 1e-5);
  }
}

// The edge and wing 0 fixed, wing 1 (at d = 1 cm) pushed by F = 0.1 mN along its direction of
// turning: static (a step of 100 s, so the mass weighs nothing), it turns by delta with
// k delta = F d cos(delta), k = 1e-4 N m, at rest angles from flat to sharply folded. The
// quadratic flat hinge could not hold the folded ones at rest.
TEST(ImplicitDihedral, AWingUnderAForceTurnsAsItsStiffnessSays) {
  const Real d = 0.01, k = 1e-4, f = 1e-4;
  Real delta = f * d / k;  // k delta = F d cos(delta), by fixed point
  for (int it = 0; it < 100; ++it)
    delta = f * d * std::cos(delta) / k;
  ASSERT_NEAR(delta, 0.01, 1e-4);
  for (const Real opening : {Real(M_PI), Real(2.5), Real(1.2)}) {
    const std::vector<Vec3> rest = hinge(d, opening);
    const std::vector<std::uint8_t> fixed = {1, 0, 1, 1};
    ImplicitMembrane m({0, 1e-6, 0, 0}, fixed, hinge_edges(rest), 100, {}, 0,
                       {{{0, 1, 2, 3}, rest_angle_of(rest), k}});
    const Vec3 turning(-std::sin(opening), std::cos(opening), 0);
    std::vector<Vec3> force(4, Vec3::Zero());
    force[1] = f * turning;
    std::vector<Vec3> x = rest, v(4, Vec3::Zero());
    ImplicitLoads loads;
    loads.force = force;
    ImplicitSolveParams exact;
    exact.tolerance = 1e-12;
    const ImplicitStepReport r = m.step(x, v, loads, exact);
    ASSERT_TRUE(r.ok);
    EXPECT_LT(r.residual, 1e-12);
    const Real turned = std::atan2(x[1].y(), x[1].x()) - opening;
    EXPECT_NEAR(std::remainder(turned, 2 * M_PI), delta, 1e-4 * delta) << "opening " << opening;
    EXPECT_NEAR(x[1].z(), rest[1].z(), 1e-9);
  }
}

TEST(ImplicitDihedral, RefusesAVertexOutOfRangeOrNamedTwice) {
  const std::vector<Vec3> rest = hinge(0.01, 2.0);
  auto make = [&](MembraneDihedral bad) {
    ImplicitMembrane m(std::vector<Real>(4, 1e-4), std::vector<std::uint8_t>(4, 0),
                       hinge_edges(rest), 0.005, {}, 0, {bad});
  };
  EXPECT_THROW(make({{0, 1, 2, 4}, 0, 1}), std::invalid_argument);
  EXPECT_THROW(make({{0, 1, 2, 2}, 0, 1}), std::invalid_argument);
  EXPECT_THROW(make({{0, 1, 2, 3}, 0, -1}), std::invalid_argument);
}

}  // namespace
}  // namespace imasim::physics
