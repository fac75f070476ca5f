// Every constraint's analytic gradient against central finite differences of its value.
#include <gtest/gtest.h>

#include <array>
#include <random>

#include "physics/attachment_constraint.hpp"
#include "physics/dihedral_constraint.hpp"
#include "physics/distance_constraint.hpp"

namespace imasim::physics {
namespace {

using V3 = Eigen::Vector3d;  // the constraint functions in double, for exact differences

constexpr double kStep = 1e-6;
constexpr double kTolerance = 1e-6;  // central differences: O(step^2) truncation + rounding

V3 random_point(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  return V3(u(rng), u(rng), u(rng));
}

// d value / d x[k][axis] by central differences.
template <std::size_t N, class F>
double central_difference(std::array<V3, N> x, std::size_t k, int axis, const F& value) {
  x[k][axis] += kStep;
  const double plus = value(x);
  x[k][axis] -= 2 * kStep;
  const double minus = value(x);
  return (plus - minus) / (2 * kStep);
}

TEST(ConstraintGradient, DistanceMatchesFiniteDifferences) {
  std::mt19937 rng(1);
  for (int trial = 0; trial < 200; ++trial) {
    const std::array<V3, 2> x = {random_point(rng), random_point(rng)};
    const double rest = 0.3;
    const DistanceEval e = evaluate_distance(x[0], x[1], rest);
    ASSERT_TRUE(e.valid);
    const std::array<V3, 2> g = {e.grad_i, e.grad_j};
    auto value = [&](const std::array<V3, 2>& y) {
      return evaluate_distance(y[0], y[1], rest).value;
    };
    for (std::size_t k = 0; k < 2; ++k) {
      for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(g[k][a], central_difference(x, k, a, value), kTolerance);
      }
    }
  }
}

// The attachment's three rows C_k = p_k - t_k have the unit axes as gradients everywhere,
// the target included (the norm |p - t| had no gradient there).
TEST(ConstraintGradient, AttachmentRowsAreTheAxesEverywhere) {
  std::mt19937 rng(2);
  for (int trial = 0; trial < 200; ++trial) {
    const std::array<V3, 1> x = {random_point(rng)};
    const V3 target = trial == 0 ? x[0] : random_point(rng);  // at the target too
    for (int k = 0; k < 3; ++k) {
      auto value = [&](const std::array<V3, 1>& y) { return attachment_values(y[0], target)[k]; };
      for (int a = 0; a < 3; ++a) {
        EXPECT_NEAR(central_difference(x, 0, a, value), a == k ? 1.0 : 0.0, kTolerance);
      }
    }
  }
}

TEST(ConstraintGradient, DihedralMatchesFiniteDifferences) {
  std::mt19937 rng(3);
  int checked = 0;
  for (int trial = 0; trial < 500; ++trial) {
    const std::array<V3, 4> x = {random_point(rng), random_point(rng), random_point(rng),
                                 random_point(rng)};
    const double rest = 0.2;
    const DihedralEval e = evaluate_dihedral(x[0], x[1], x[2], x[3], rest);
    ASSERT_TRUE(e.valid);
    // Too close to the +-pi cut the difference quotient straddles the jump of the wrap.
    if (std::abs(e.value) > 3.0) continue;
    auto value = [&](const std::array<V3, 4>& y) {
      return evaluate_dihedral(y[0], y[1], y[2], y[3], rest).value;
    };
    // Relative tolerance: near-degenerate random triangles have large gradients.
    for (std::size_t k = 0; k < 4; ++k) {
      for (int a = 0; a < 3; ++a) {
        const double fd = central_difference(x, k, a, value);
        EXPECT_NEAR(e.grad[k][a], fd, kTolerance * std::max(1.0, std::abs(fd)))
            << "trial " << trial << " vertex " << k << " axis " << a;
      }
    }
    ++checked;
  }
  EXPECT_GT(checked, 400);
}

TEST(ConstraintGradient, DihedralGradientsAreTranslationAndRotationInvariant) {
  std::mt19937 rng(4);
  for (int trial = 0; trial < 100; ++trial) {
    const std::array<V3, 4> x = {random_point(rng), random_point(rng), random_point(rng),
                                 random_point(rng)};
    const DihedralEval e = evaluate_dihedral(x[0], x[1], x[2], x[3], 0.0);
    V3 force = V3::Zero(), torque = V3::Zero();
    for (std::size_t k = 0; k < 4; ++k) {
      force += e.grad[k];
      torque += x[k].cross(e.grad[k]);
    }
    const double scale = e.grad[0].norm() + e.grad[1].norm();
    EXPECT_LT(force.norm(), 1e-9 * scale);
    EXPECT_LT(torque.norm(), 1e-9 * scale);
  }
}

}  // namespace
}  // namespace imasim::physics
