// The fascia's Newton matrix (physics/implicit_membrane.hpp's, built here from the same mesh,
// springs and hinges: 24 x 24 vertices over 50 mm, perimeter fixed, each edge taut at 2 % strain
// and turned out of plane, plus one body joined to every vertex as a tool's proxy is) factored
// two ways, in one run so that their ratio is the figure:
//   BM_MembraneFactor/block:  physics::BlockCholesky, 3 x 3 blocks;
//   BM_MembraneFactor/eigen_scalar: Eigen's SimplicialLDLT on the same matrix as scalars (AMD
//   order).
// Counters: the block rows and the factor's blocks below the diagonal. BM_MembraneSolve: one
// solve with the factor.
#include <benchmark/benchmark.h>

#include <Eigen/SparseCholesky>
#include <algorithm>
#include <cmath>

#include "geometry/grid_rectangle.hpp"
#include "physics/block_cholesky.hpp"
#include "physics/membrane_springs.hpp"

namespace {

using imasim::Mat3;
using imasim::Real;
using imasim::Vec3;
using namespace imasim::physics;

struct MembraneMatrix {
  std::uint32_t rows = 0;
  std::vector<BlockCholesky::Pair> pairs;
  std::vector<Mat3> diagonal, off_diagonal;
};

MembraneMatrix fascia_matrix() {
  constexpr std::uint32_t n = 24;
  const auto mesh = imasim::geometry::make_grid_rectangle({0.05, 0.05, n, n});
  const StiffeningMembrane fascia{0.1e6, 2.65e6, 0.05, 1e-3, 1100};
  const auto masses = membrane_masses(mesh, fascia);
  const auto edges = membrane_springs(mesh, fascia);
  const auto hinges = membrane_hinges(mesh, 0.1e6 * 1e-9 / (12 * (1 - 0.45 * 0.45)));
  std::vector<std::uint32_t> row(mesh.vertices.size(), ~0u);
  MembraneMatrix m;
  for (std::uint32_t j = 1; j + 1 < n; ++j)
    for (std::uint32_t i = 1; i + 1 < n; ++i)
      row[imasim::geometry::grid_index(i, j, n)] = m.rows++;
  const std::uint32_t body = m.rows++;
  m.diagonal.assign(m.rows, Mat3::Zero());
  for (std::size_t v = 0; v < row.size(); ++v)
    if (row[v] != ~0u) m.diagonal[row[v]] = masses[v] / (0.005 * 0.005) * Mat3::Identity();
  m.diagonal[body] = 2000 * Mat3::Identity();
  std::vector<std::pair<BlockCholesky::Pair, Mat3>> blocks;
  auto couple = [&](std::uint32_t a, std::uint32_t b, const Mat3& k) {
    if (a == ~0u || b == ~0u) return;
    if (a == b) {
      m.diagonal[a] += k;
      return;
    }
    blocks.push_back({{std::min(a, b), std::max(a, b)}, k});
  };
  for (const MembraneEdge& e : edges) {
    // Taut (tension at 2 % strain across) and out of plane, as under a tool.
    const Vec3 d = (mesh.vertices[e.i] - mesh.vertices[e.j]).normalized() + Vec3(0, 0.1, 0);
    const Vec3 u = d.normalized();
    const Real along = e.spring.linear_stiffness, across = 0.02 * e.spring.toe_stiffness;
    const Mat3 k = along * u * u.transpose() + across * (Mat3::Identity() - u * u.transpose());
    couple(row[e.i], row[e.i], k);
    couple(row[e.j], row[e.j], k);
    couple(row[e.i], row[e.j], -k);
  }
  for (const MembraneHinge& h : hinges)
    for (std::uint32_t p = 0; p < 4; ++p)
      for (std::uint32_t q = p; q < 4; ++q)
        couple(row[h.v[p]], row[h.v[q]], h.stiffness * h.w[p] * h.w[q] * Mat3::Identity());
  for (std::uint32_t a = 0; a < body; ++a)  // a contact's k n n^T at every tenth vertex
    couple(a, body, a % 10 ? Mat3::Zero() : Mat3(-1e5 * Vec3::UnitY() * Vec3::UnitY().transpose()));
  for (std::uint32_t a = 0; a < body; a += 10) {
    m.diagonal[a] += 1e5 * Vec3::UnitY() * Vec3::UnitY().transpose();
    m.diagonal[body] += 1e5 * Vec3::UnitY() * Vec3::UnitY().transpose();
  }
  std::sort(blocks.begin(), blocks.end(),
            [](const auto& x, const auto& y) { return x.first < y.first; });
  for (const auto& [pair, k] : blocks) {
    if (!m.pairs.empty() && m.pairs.back() == pair) {
      m.off_diagonal.back() += k;
      continue;
    }
    m.pairs.push_back(pair);
    m.off_diagonal.push_back(k);
  }
  return m;
}

void BM_MembraneFactor(benchmark::State& bench, bool eigen_scalar) {
  const MembraneMatrix m = fascia_matrix();
  BlockCholesky cholesky;
  cholesky.analyse(m.rows, m.pairs);
  if (!eigen_scalar) {
    for (auto _ : bench)
      if (!cholesky.factorize(m.diagonal, m.off_diagonal)) bench.SkipWithError("not factored");
  } else {
    std::vector<Eigen::Triplet<Real>> entries;
    auto put = [&](std::uint32_t a, std::uint32_t b, const Mat3& k) {
      for (std::uint32_t r = 0; r < 3; ++r)
        for (std::uint32_t c = 0; c < 3; ++c)
          entries.emplace_back(3 * a + r, 3 * b + c, k(r, c));
    };
    for (std::uint32_t a = 0; a < m.rows; ++a)
      put(a, a, m.diagonal[a]);
    for (std::size_t s = 0; s < m.pairs.size(); ++s) {
      put(m.pairs[s].first, m.pairs[s].second, m.off_diagonal[s]);
      put(m.pairs[s].second, m.pairs[s].first, m.off_diagonal[s].transpose());
    }
    Eigen::SparseMatrix<Real> a(3 * m.rows, 3 * m.rows);
    a.setFromTriplets(entries.begin(), entries.end());
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<Real>> scalar;
    scalar.analyzePattern(a);
    for (auto _ : bench) {
      scalar.factorize(a);
      if (scalar.info() != Eigen::Success) bench.SkipWithError("not factored");
    }
  }
  bench.counters["block_rows"] = m.rows;
  bench.counters["factor_blocks"] = double(cholesky.factor_blocks());
}
// One solve with the factor (a Newton step's direction once the matrix is factored).
void BM_MembraneSolve(benchmark::State& bench) {
  const MembraneMatrix m = fascia_matrix();
  BlockCholesky cholesky;
  cholesky.analyse(m.rows, m.pairs);
  if (!cholesky.factorize(m.diagonal, m.off_diagonal)) bench.SkipWithError("not factored");
  std::vector<Real> rhs(3 * std::size_t(m.rows));
  for (auto _ : bench) {
    for (std::size_t i = 0; i < rhs.size(); ++i)
      rhs[i] = Real(i % 7) - 3;
    cholesky.solve(rhs);
    benchmark::DoNotOptimize(rhs.data());
  }
}
BENCHMARK(BM_MembraneSolve)->Unit(benchmark::kMicrosecond);
BENCHMARK_CAPTURE(BM_MembraneFactor, block, false)->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_MembraneFactor, eigen_scalar, true)->Unit(benchmark::kMillisecond);

}  // namespace
