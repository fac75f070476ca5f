// The SIMD batch projection equals the scalar projection, lane by lane, including lanes that are
// degenerate, far from rest (the libm atan2 path) or fully fixed.
#include <gtest/gtest.h>

#include <random>

#include "physics/dihedral_batch.hpp"
#include "precision.hpp"

namespace imasim::physics {
namespace {

struct Batch {
  std::vector<Vec3> x;
  std::vector<Real> w;
  std::vector<DihedralRow> rows;
  std::vector<Real> lambda;
};

// kDihedralBatch hinges on disjoint particles 4k .. 4k+3, randomly bent around a rest angle.
Batch make_batch(std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  Batch b;
  for (std::size_t k = 0; k < kDihedralBatch; ++k) {
    const auto base = static_cast<std::uint32_t>(4 * k);
    const double bend = 0.3 * u(rng);
    b.x.push_back(Vec3(0.5 + 0.1 * u(rng), bend, -1));         // wing 0
    b.x.push_back(Vec3(0.5 + 0.1 * u(rng), 0.2 * u(rng), 1));  // wing 1
    b.x.push_back(Vec3(0, 0, 0.05 * u(rng)));                  // edge start
    b.x.push_back(Vec3(1, 0.05 * u(rng), 0));                  // edge end
    for (int j = 0; j < 4; ++j)
      b.w.push_back(Real(1 + u(rng) * 0.5));
    DihedralRow row;
    row.p = {base, base + 1, base + 2, base + 3};
    const double rest = 0.4 * u(rng);
    row.rest_cos = Real(std::cos(rest));
    row.rest_sin = Real(std::sin(rest));
    row.material = static_cast<MaterialId>(k % 2);
    b.rows.push_back(row);
    b.lambda.push_back(Real(0.01 * u(rng)));
  }
  // Lane 1: wing 0 on the edge line (degenerate). Lane 2: folded far from rest (atan2 path).
  // Lane 3: all four particles fixed.
  b.x[4] = 0.5 * (b.x[6] + b.x[7]);
  b.x[8] = Vec3(0.5, std::sin(2.5), std::cos(2.5));
  for (int j = 12; j < 16; ++j)
    b.w[j] = 0;
  return b;
}

TEST(DihedralBatch, EqualsTheScalarProjectionLaneByLane) {
  static_assert(kDihedralBatch >= 4);
  const std::array<ProjectionTerms, 2> terms = {ProjectionTerms{1, Real(0.5)},
                                                ProjectionTerms{Real(0.7), 0}};
  for (std::uint32_t seed = 1; seed <= 50; ++seed) {
    Batch scalar = make_batch(seed), batch = make_batch(seed);
    for (std::size_t k = 0; k < kDihedralBatch; ++k) {
      project_dihedral(scalar.rows[k], scalar.lambda[k],
                       {scalar.x.data(), scalar.w.data(), terms.data()});
    }
    project_dihedral_batch(batch.rows.data(), batch.lambda.data(),
                           {batch.x.data(), batch.w.data(), terms.data()});
    const Batch untouched = make_batch(seed);
    for (std::size_t i = 0; i < scalar.x.size(); ++i) {
      // Same formulas, evaluated in a different order (relative to the edge start): equal to
      // the rounding of the correction.
      EXPECT_LT((batch.x[i] - scalar.x[i]).norm(), test::ulps(64, 1))
          << "seed " << seed << " particle " << i;
    }
    for (std::size_t k = 0; k < kDihedralBatch; ++k) {
      EXPECT_NEAR(batch.lambda[k], scalar.lambda[k], test::ulps(64, 1)) << "lane " << k;
    }
    // The degenerate and the fixed lanes did not move; the far lane did.
    for (int i : {4, 5, 6, 7, 12, 13, 14, 15})
      EXPECT_EQ(batch.x[i], untouched.x[i]);
    EXPECT_NE(batch.x[8], untouched.x[8]);
    EXPECT_EQ(batch.lambda[1], untouched.lambda[1]);
  }
}

}  // namespace
}  // namespace imasim::physics
