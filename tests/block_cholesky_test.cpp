// The 3 x 3 block sparse Cholesky (physics/block_cholesky.hpp) against the residual A x - b and
// against Eigen's scalar SimplicialLDLT on the same matrices: a mesh's pattern with a body joined
// to every vertex, as the fascia's Newton system has; blocks given in either orientation; a matrix
// that is not positive definite refused and the next one factored; a pattern it cannot take
// refused.
#include <gtest/gtest.h>

#include <Eigen/SparseCholesky>
#include <Eigen/SparseCore>
#include <cmath>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>

#include "geometry/grid_rectangle.hpp"
#include "physics/block_cholesky.hpp"

namespace imasim::physics {
namespace {

using Pair = BlockCholesky::Pair;
constexpr Real kEpsilon = std::numeric_limits<Real>::epsilon();

// A symmetric positive definite block matrix on a pattern: random off-diagonal blocks (not
// symmetric themselves) and diagonal blocks that dominate them.
struct BlockMatrix {
  std::uint32_t nodes = 0;
  std::vector<Pair> pairs;
  std::vector<Mat3> diagonal, off_diagonal;

  Eigen::SparseMatrix<Real> sparse() const {
    std::vector<Eigen::Triplet<Real>> entries;
    auto put = [&](std::uint32_t a, std::uint32_t b, const Mat3& block) {
      for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c)
          entries.emplace_back(3 * a + r, 3 * b + c, block(r, c));
    };
    for (std::uint32_t n = 0; n < nodes; ++n)
      put(n, n, diagonal[n]);
    for (std::size_t s = 0; s < pairs.size(); ++s) {
      put(pairs[s].first, pairs[s].second, off_diagonal[s]);
      put(pairs[s].second, pairs[s].first, off_diagonal[s].transpose());
    }
    Eigen::SparseMatrix<Real> a(3 * nodes, 3 * nodes);
    a.setFromTriplets(entries.begin(), entries.end());
    return a;
  }
};

// A 12 x 12 grid's triangle edges, each vertex also joined to the vertex two along (as hinges
// join wings), and one body node joined to every vertex.
BlockMatrix mesh_matrix(std::uint32_t seed) {
  const geometry::TriangleMesh mesh = geometry::make_grid_rectangle({0.05, 0.05, 12, 12});
  const auto vertices = static_cast<std::uint32_t>(mesh.vertices.size());
  std::set<Pair> links;
  for (const auto& t : mesh.triangles)
    for (int c = 0; c < 3; ++c)
      links.insert(std::minmax(t[c], t[(c + 1) % 3]));
  for (std::uint32_t v = 0; v + 2 < vertices; ++v)
    links.insert({v, v + 2});
  for (std::uint32_t v = 0; v < vertices; ++v)
    links.insert({v, vertices});
  BlockMatrix m;
  m.nodes = vertices + 1;
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  std::vector<Real> row_sum(m.nodes, 0);
  for (const Pair& p : links) {
    // Alternate the orientation, so both appear.
    m.pairs.push_back(m.pairs.size() % 2 ? p : Pair{p.second, p.first});
    Mat3 block;
    for (int k = 0; k < 9; ++k)
      block(k % 3, k / 3) = Real(uniform(random));
    m.off_diagonal.push_back(block);
    row_sum[p.first] += block.cwiseAbs().sum();
    row_sum[p.second] += block.cwiseAbs().sum();
  }
  for (std::uint32_t n = 0; n < m.nodes; ++n) {
    Mat3 b;
    for (int k = 0; k < 9; ++k)
      b(k % 3, k / 3) = Real(uniform(random));
    m.diagonal.push_back(b * b.transpose() + (row_sum[n] + 1) * Mat3::Identity());
  }
  return m;
}

using Vector = Eigen::Matrix<Real, Eigen::Dynamic, 1>;

// |u - v| in a plain loop (GCC 12 warns falsely inside Eigen's AVX-512 reductions).
Real distance(const Vector& u, const Vector& v) {
  Real sum = 0;
  for (Eigen::Index k = 0; k < u.size(); ++k)
    sum += (u[k] - v[k]) * (u[k] - v[k]);
  return std::sqrt(sum);
}

Real length(const Vector& u) {
  return distance(u, Vector::Zero(u.size()));
}

Vector random_vector(std::uint32_t rows, std::uint32_t seed) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> uniform(-1, 1);
  Vector b(rows);
  for (std::uint32_t r = 0; r < rows; ++r)
    b[r] = Real(uniform(random));
  return b;
}

TEST(BlockCholesky, SolvesAMeshsSystemAsDenseCholeskyDoes) {
  const BlockMatrix m = mesh_matrix(1);
  BlockCholesky cholesky;
  cholesky.analyse(m.nodes, m.pairs);
  ASSERT_TRUE(cholesky.factorize(m.diagonal, m.off_diagonal));
  const auto a = m.sparse();
  const auto b = random_vector(3 * m.nodes, 2);
  Vector x = b;
  cholesky.solve({x.data(), std::size_t(x.size())});
  EXPECT_LT(distance(a * x, b), 100 * kEpsilon * length(b));
  // The factor has fill beyond the matrix's pattern (a grid's elimination fills in), else this
  // would not test the fill's rows.
  EXPECT_GT(cholesky.factor_blocks(), m.pairs.size());
}

TEST(BlockCholesky, AgreesWithEigensScalarFactorisationOnTheSameMatrix) {
  const BlockMatrix m = mesh_matrix(3);
  BlockCholesky cholesky;
  cholesky.analyse(m.nodes, m.pairs);
  ASSERT_TRUE(cholesky.factorize(m.diagonal, m.off_diagonal));
  const Eigen::SimplicialLDLT<Eigen::SparseMatrix<Real>> scalar(m.sparse());
  ASSERT_EQ(scalar.info(), Eigen::Success);
  const auto b = random_vector(3 * m.nodes, 4);
  Vector x = b;
  cholesky.solve({x.data(), std::size_t(x.size())});
  const Vector reference = scalar.solve(b);
  EXPECT_LT(distance(x, reference), 100 * kEpsilon * length(reference));
}

TEST(BlockCholesky, ABlockGivenTransposedForTheReversedPairIsTheSameMatrix) {
  BlockMatrix m = mesh_matrix(5);
  BlockCholesky forward;
  forward.analyse(m.nodes, m.pairs);
  ASSERT_TRUE(forward.factorize(m.diagonal, m.off_diagonal));
  for (std::size_t s = 0; s < m.pairs.size(); ++s) {
    m.pairs[s] = {m.pairs[s].second, m.pairs[s].first};
    m.off_diagonal[s].transposeInPlace();
  }
  BlockCholesky reversed;
  reversed.analyse(m.nodes, m.pairs);
  ASSERT_TRUE(reversed.factorize(m.diagonal, m.off_diagonal));
  const auto b = random_vector(3 * m.nodes, 6);
  Vector x = b, y = b;
  forward.solve({x.data(), std::size_t(x.size())});
  reversed.solve({y.data(), std::size_t(y.size())});
  EXPECT_LT(distance(x, y), 100 * kEpsilon * length(x));
}

TEST(BlockCholesky, ReadsOnlyTheLowerTriangleOfADiagonalBlock) {
  BlockMatrix m = mesh_matrix(7);
  BlockCholesky cholesky;
  cholesky.analyse(m.nodes, m.pairs);
  const auto a = m.sparse();
  for (Mat3& d : m.diagonal)
    d.triangularView<Eigen::StrictlyUpper>().setConstant(Real(1e30));
  ASSERT_TRUE(cholesky.factorize(m.diagonal, m.off_diagonal));
  const auto b = random_vector(3 * m.nodes, 8);
  Vector x = b;
  cholesky.solve({x.data(), std::size_t(x.size())});
  EXPECT_LT(distance(a * x, b), 100 * kEpsilon * length(b));
}

TEST(BlockCholesky, RefusesAMatrixNotPositiveDefiniteAndFactorsTheNext) {
  BlockMatrix m = mesh_matrix(9);
  BlockCholesky cholesky;
  cholesky.analyse(m.nodes, m.pairs);
  const std::vector<Mat3> good = m.diagonal;
  m.diagonal[m.nodes / 2](1, 1) = -1;  // an indefinite pivot
  EXPECT_FALSE(cholesky.factorize(m.diagonal, m.off_diagonal));
  m.diagonal = good;
  m.diagonal[0](0, 0) = std::numeric_limits<Real>::quiet_NaN();
  EXPECT_FALSE(cholesky.factorize(m.diagonal, m.off_diagonal));
  m.diagonal = good;
  ASSERT_TRUE(cholesky.factorize(m.diagonal, m.off_diagonal));
  const auto a = m.sparse();
  const auto b = random_vector(3 * m.nodes, 10);
  Vector x = b;
  cholesky.solve({x.data(), std::size_t(x.size())});
  EXPECT_LT(distance(a * x, b), 100 * kEpsilon * length(b));
}

TEST(BlockCholesky, ABlockDiagonalMatrixAndAnEmptyOne) {
  BlockCholesky cholesky;
  const std::vector<Mat3> diagonal = {2 * Mat3::Identity(), 4 * Mat3::Identity()};
  cholesky.analyse(2, {});
  ASSERT_TRUE(cholesky.factorize(diagonal, {}));
  std::vector<Real> x = {2, 4, 6, 4, 8, 12};
  cholesky.solve({x.data(), std::size_t(x.size())});
  const std::vector<Real> expected = {1, 2, 3, 1, 2, 3};
  for (std::size_t r = 0; r < x.size(); ++r)
    EXPECT_NEAR(x[r], expected[r], 4 * kEpsilon * expected[r]) << "row " << r;
  EXPECT_EQ(cholesky.factor_blocks(), 0u);
  BlockCholesky empty;
  empty.analyse(0, {});
  EXPECT_TRUE(empty.factorize({}, {}));
  std::vector<Real> none;
  empty.solve(none);
}

TEST(BlockCholesky, RefusesAPatternItCannotTakeAndSizesThatDoNotMatch) {
  BlockCholesky cholesky;
  auto refusal = [&](std::vector<Pair> pairs) {
    try {
      cholesky.analyse(3, pairs);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(refusal({{0, 3}}).find("pair 0 (0, 3) out of range"), std::string::npos);
  EXPECT_NE(refusal({{0, 1}, {2, 2}}).find("pair 1 (2, 2) is on the diagonal"), std::string::npos);
  EXPECT_NE(refusal({{0, 1}, {1, 0}}).find("(0, 1) is named twice"), std::string::npos);
  cholesky.analyse(3, std::vector<Pair>{{0, 1}});
  const std::vector<Mat3> two(2, Mat3::Identity()), three(3, Mat3::Identity());
  const std::vector<Mat3> half(1, Real(0.5) * Mat3::Identity());
  EXPECT_THROW(cholesky.factorize(two, half), std::invalid_argument);
  EXPECT_THROW(cholesky.factorize(three, {}), std::invalid_argument);
  ASSERT_TRUE(cholesky.factorize(three, half));
  std::vector<Real> short_rhs(8, 1);
  EXPECT_THROW(cholesky.solve(short_rhs), std::invalid_argument);
}

}  // namespace
}  // namespace imasim::physics
