// Dihedral constraint (eq. 3): value at rest, sign convention, continuity, degenerate input.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "math/angles.hpp"
#include "physics/dihedral_constraint.hpp"

namespace imasim::physics {
namespace {

using V3 = Eigen::Vector3d;  // evaluation in double; projections below in Real

double deg(double d) {
  return d * std::numbers::pi / 180;
}

// Shared edge a=(0,0,0) -> b=(1,0,0); wings at z = -1 and z = +1, raised to height y. With this
// order both faces' normals point along +y when flat.
struct Hinge {
  V3 w0, w1, a = V3(0, 0, 0), b = V3(1, 0, 0);
};

Hinge hinge_with_wings_at(double y0, double y1) {
  return {V3(0.5, y0, -1), V3(0.5, y1, 1)};
}

// Wing 0 rotated by `angle` about the edge (x axis) from the flat position, wing 1 flat.
Hinge hinge_folded(double angle) {
  return {V3(0.5, std::sin(angle), -std::cos(angle)), V3(0.5, 0, 1)};
}

double angle_of(const Hinge& h) {
  return dihedral_angle(h.w0, h.w1, h.a, h.b);
}

TEST(Dihedral, ZeroWhenFlatAndZeroAtRest) {
  EXPECT_EQ(angle_of(hinge_with_wings_at(0, 0)), 0.0);
  const Hinge bent = hinge_with_wings_at(0.3, -0.2);
  const double rest = angle_of(bent);
  EXPECT_NE(rest, 0.0);
  // The rest angle enters as its cosine and sine, so "zero" is zero to a few units of rounding.
  EXPECT_NEAR(evaluate_dihedral(bent.w0, bent.w1, bent.a, bent.b, rest).value, 0.0, 4e-16);
}

TEST(Dihedral, SignConvention) {
  // Wings folding towards the side the normals point to (+y): negative; away from it: positive.
  EXPECT_LT(angle_of(hinge_with_wings_at(0.3, 0.3)), 0.0);
  EXPECT_GT(angle_of(hinge_with_wings_at(-0.3, -0.3)), 0.0);
  // Antisymmetric, and equal to the geometric fold angle.
  EXPECT_NEAR(angle_of(hinge_folded(0.4)), -angle_of(hinge_folded(-0.4)), 1e-15);
  EXPECT_NEAR(angle_of(hinge_folded(-0.4)), 0.4, 1e-12);
  EXPECT_NEAR(angle_of(hinge_folded(-2.5)), 2.5, 1e-12);
}

TEST(Dihedral, ContinuousThroughZero) {
  double previous = angle_of(hinge_folded(-1e-3));
  for (int k = -999; k <= 1000; ++k) {
    const double a = angle_of(hinge_folded(k * 1e-6));
    EXPECT_NEAR(a, -k * 1e-6, 1e-12);
    EXPECT_LT(std::abs(a - previous), 2e-6);
    previous = a;
  }
}

TEST(Dihedral, ConstraintIsContinuousThroughPiWithARestAngleNearPi) {
  // Rest folded by 179 deg; fold through 180 deg: C moves smoothly, no 2 pi jump.
  const double rest = angle_of(hinge_folded(deg(-179)));
  ASSERT_NEAR(rest, deg(179), 1e-12);
  double previous = 0;
  for (int k = 0; k <= 400; ++k) {
    const double fold = deg(-179 - 0.005 * k);  // 179 .. 181 deg
    const Hinge h = hinge_folded(fold);
    const DihedralEval e = evaluate_dihedral(h.w0, h.w1, h.a, h.b, rest);
    ASSERT_TRUE(e.valid);
    EXPECT_NEAR(e.value, deg(0.005 * k), 1e-9);
    if (k > 0) {
      EXPECT_LT(std::abs(e.value - previous), 1e-3);
    }
    previous = e.value;
  }
}

TEST(Dihedral, DegenerateTrianglesGiveNoNaN) {
  const V3 a(0, 0, 0), b(1, 0, 0);
  const Hinge h = hinge_with_wings_at(0, 0);
  const std::array<std::array<V3, 4>, 4> cases = {{
      {V3(0.5, 0, 0), h.w1, a, b},     // wing 0 on the edge line: zero-area face
      {a, h.w1, a, b},                 // wing 0 on an edge vertex
      {h.w0, h.w1, a, a},              // zero-length shared edge
      {V3(0.5, 1e-9, 0), h.w1, a, b},  // nearly degenerate
  }};
  for (const auto& c : cases) {
    const DihedralEval e = evaluate_dihedral(c[0], c[1], c[2], c[3], 0.3);
    EXPECT_FALSE(e.valid);
    EXPECT_TRUE(std::isfinite(e.value));
    for (const V3& g : e.grad)
      EXPECT_TRUE(g.allFinite());
  }
}

TEST(Dihedral, ProjectionLeavesDegenerateConfigurationsFinite) {
  std::array<Vec3, 4> x = {Vec3(0.5, 0, 0), Vec3(0.5, 0, 1), Vec3(0, 0, 0), Vec3(1, 0, 0)};
  const std::array<Real, 4> w = {1, 1, 1, 1};
  const ProjectionTerms terms{1, 0};
  DihedralRow row;
  row.p = {0, 1, 2, 3};
  row.rest_cos = Real(std::cos(1.0));
  row.rest_sin = Real(std::sin(1.0));
  Real lambda = 0;
  project_dihedral(row, lambda, {x.data(), w.data(), &terms});
  for (const Vec3& p : x)
    EXPECT_TRUE(p.allFinite());
  EXPECT_EQ(lambda, 0.0);
}

TEST(Dihedral, OneRigidProjectionRestoresASmallFold) {
  // PBD with stiffness 1 is a Newton step on C: a small fold returns almost to rest.
  const Hinge h = hinge_folded(0.05);
  std::array<Vec3, 4> x = {h.w0.cast<Real>(), h.w1.cast<Real>(), h.a.cast<Real>(),
                           h.b.cast<Real>()};
  const std::array<Real, 4> w = {1, 1, 1, 1};
  const ProjectionTerms terms{1, 0};
  DihedralRow row;
  row.p = {0, 1, 2, 3};
  Real lambda = 0;
  project_dihedral(row, lambda, {x.data(), w.data(), &terms});
  EXPECT_LT(std::abs(dihedral_angle(x[0], x[1], x[2], x[3])), Real(0.05 * 0.05));
}

}  // namespace
}  // namespace imasim::physics
