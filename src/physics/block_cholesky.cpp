#include "physics/block_cholesky.hpp"

#include <Eigen/Cholesky>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>
#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>

namespace imasim::physics {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

std::string pair_name(std::size_t s, const BlockCholesky::Pair& p) {
  return "block Cholesky: pair " + std::to_string(s) + " (" + std::to_string(p.first) + ", " +
         std::to_string(p.second) + ")";
}

// The inverse of a lower triangular 3 x 3 block with a positive diagonal, written out (Eigen's
// triangular solve with a matrix right-hand side takes its blocked path here).
Mat3 lower_inverse(const Mat3& l) {
  const Real a = 1 / l(0, 0), c = 1 / l(1, 1), f = 1 / l(2, 2);
  Mat3 inverse = Mat3::Zero();
  inverse(0, 0) = a;
  inverse(1, 1) = c;
  inverse(2, 2) = f;
  inverse(1, 0) = -l(1, 0) * a * c;
  inverse(2, 1) = -l(2, 1) * c * f;
  inverse(2, 0) = (l(1, 0) * l(2, 1) - l(1, 1) * l(2, 0)) * a * c * f;
  return inverse;
}

}  // namespace

void BlockCholesky::analyse(std::uint32_t nodes, std::span<const Pair> pairs) {
  std::vector<Pair> sorted;
  sorted.reserve(pairs.size());
  for (std::size_t s = 0; s < pairs.size(); ++s) {
    const auto [a, b] = pairs[s];
    if (a >= nodes || b >= nodes)
      throw std::invalid_argument(pair_name(s, pairs[s]) + " out of range");
    if (a == b) throw std::invalid_argument(pair_name(s, pairs[s]) + " is on the diagonal");
    sorted.emplace_back(std::min(a, b), std::max(a, b));
  }
  std::sort(sorted.begin(), sorted.end());
  if (const auto twice = std::adjacent_find(sorted.begin(), sorted.end()); twice != sorted.end())
    throw std::invalid_argument("block Cholesky: the pair (" + std::to_string(twice->first) + ", " +
                                std::to_string(twice->second) + ") is named twice");
  nodes_ = nodes;

  // The elimination order: approximate minimum degree on the block graph.
  order_.resize(nodes);
  if (nodes > 0) {
    Eigen::SparseMatrix<double> graph(nodes, nodes);
    std::vector<Eigen::Triplet<double>> links;
    links.reserve(2 * pairs.size() + nodes);
    for (std::uint32_t a = 0; a < nodes; ++a)
      links.emplace_back(a, a, 1.0);
    for (const auto& [a, b] : sorted) {
      links.emplace_back(a, b, 1.0);
      links.emplace_back(b, a, 1.0);
    }
    graph.setFromTriplets(links.begin(), links.end());
    Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> eliminated;
    Eigen::AMDOrdering<int>()(graph, eliminated);  // indices()[k]: the node eliminated k-th
    for (std::uint32_t k = 0; k < nodes; ++k)
      order_[k] = static_cast<std::uint32_t>(eliminated.indices()[k]);
  }
  std::vector<std::uint32_t> position(nodes);
  for (std::uint32_t k = 0; k < nodes; ++k)
    position[order_[k]] = k;

  // Row k's blocks left of the diagonal, sorted by column.
  entry_start_.assign(nodes + 1, 0);
  for (const auto& [a, b] : pairs)
    ++entry_start_[std::max(position[a], position[b]) + 1];
  for (std::uint32_t k = 0; k < nodes; ++k)
    entry_start_[k + 1] += entry_start_[k];
  entries_.resize(pairs.size());
  std::vector<std::uint32_t> next(entry_start_.begin(), entry_start_.end() - 1);
  for (std::size_t s = 0; s < pairs.size(); ++s) {
    const std::uint32_t pa = position[pairs[s].first], pb = position[pairs[s].second];
    // The block in row max, column min: the stored (a, b) when a comes later, else its transpose.
    entries_[next[std::max(pa, pb)]++] = {std::min(pa, pb), static_cast<std::uint32_t>(s), pa < pb};
  }
  for (std::uint32_t k = 0; k < nodes; ++k)
    std::sort(entries_.begin() + entry_start_[k], entries_.begin() + entry_start_[k + 1],
              [](const Entry& x, const Entry& y) { return x.column < y.column; });

  // The elimination tree (Liu's algorithm, path-compressed ancestors).
  parent_.assign(nodes, kNone);
  std::vector<std::uint32_t> ancestor(nodes, kNone);
  for (std::uint32_t k = 0; k < nodes; ++k)
    for (std::uint32_t e = entry_start_[k]; e < entry_start_[k + 1]; ++e)
      for (std::uint32_t i = entries_[e].column; i != kNone && i < k;) {
        const std::uint32_t up = ancestor[i];
        ancestor[i] = k;
        if (up == kNone) parent_[i] = k;
        i = up;
      }

  // Column counts: row k of L is the union of the tree paths from its entries' columns up to k.
  mark_.assign(nodes, kNone);
  std::vector<std::uint32_t> count(nodes, 0);
  for (std::uint32_t k = 0; k < nodes; ++k) {
    mark_[k] = k;
    for (std::uint32_t e = entry_start_[k]; e < entry_start_[k + 1]; ++e)
      for (std::uint32_t i = entries_[e].column; mark_[i] != k; i = parent_[i]) {
        mark_[i] = k;
        ++count[i];
      }
  }
  column_start_.assign(nodes + 1, 0);
  for (std::uint32_t j = 0; j < nodes; ++j)
    column_start_[j + 1] = column_start_[j] + count[j];
  row_of_.assign(column_start_[nodes], 0);
  factor_.assign(column_start_[nodes], Mat3::Zero());
  pivot_.assign(nodes, Mat3::Identity());
  pivot_inverse_t_.assign(nodes, Mat3::Identity());
  filled_.assign(nodes, 0);
  stack_.assign(nodes, 0);
  row_.assign(nodes, Mat3::Zero());
  permuted_.assign(nodes, Vec3::Zero());
}

bool BlockCholesky::factorize(std::span<const Mat3> diagonal, std::span<const Mat3> off_diagonal) {
  if (diagonal.size() != nodes_ || off_diagonal.size() != entries_.size())
    throw std::invalid_argument("block Cholesky: " + std::to_string(diagonal.size()) +
                                " diagonal and " + std::to_string(off_diagonal.size()) +
                                " off-diagonal blocks for a pattern of " + std::to_string(nodes_) +
                                " and " + std::to_string(entries_.size()));
  std::copy(column_start_.begin(), column_start_.end() - 1, filled_.begin());
  std::fill(mark_.begin(), mark_.end(), kNone);
  for (std::uint32_t k = 0; k < nodes_; ++k) {
    // Row k's pattern in L, in topological order, at stack_[top, nodes_); its values scattered
    // into row_ (zero elsewhere).
    std::uint32_t top = nodes_;
    mark_[k] = k;
    for (std::uint32_t e = entry_start_[k]; e < entry_start_[k + 1]; ++e) {
      const Entry& entry = entries_[e];
      row_[entry.column] =
          entry.transposed ? off_diagonal[entry.slot].transpose() : off_diagonal[entry.slot];
      std::uint32_t length = 0;
      for (std::uint32_t i = entry.column; mark_[i] != k; i = parent_[i]) {
        stack_[length++] = i;
        mark_[i] = k;
      }
      while (length > 0)
        stack_[--top] = stack_[--length];
    }
    Mat3 pivot = diagonal[order_[k]].selfadjointView<Eigen::Lower>();
    for (std::uint32_t p = top; p < nodes_; ++p) {
      const std::uint32_t j = stack_[p];
      const Mat3 l = row_[j] * pivot_inverse_t_[j];  // L_kj = (A_kj - sum ...) L_jj^-T
      row_[j].setZero();
      for (std::uint32_t q = column_start_[j]; q < filled_[j]; ++q)
        row_[row_of_[q]].noalias() -= l * factor_[q].transpose();
      pivot.noalias() -= l * l.transpose();
      row_of_[filled_[j]] = k;
      factor_[filled_[j]++] = l;
    }
    const Eigen::LLT<Mat3> pivot_factor(pivot);
    if (pivot_factor.info() != Eigen::Success || !pivot.allFinite()) return false;
    pivot_[k] = pivot_factor.matrixL();
    pivot_inverse_t_[k] = lower_inverse(pivot_[k]).transpose();
  }
  return true;
}

void BlockCholesky::solve(std::span<Real> rhs) const {
  if (rhs.size() != 3 * std::size_t(nodes_))
    throw std::invalid_argument("block Cholesky: a right-hand side of " +
                                std::to_string(rhs.size()) + " for " + std::to_string(nodes_) +
                                " nodes");
  for (std::uint32_t k = 0; k < nodes_; ++k)
    permuted_[k] = Eigen::Map<const Vec3>(rhs.data() + 3 * std::size_t(order_[k]));
  for (std::uint32_t j = 0; j < nodes_; ++j) {  // L y = b
    const Vec3 y = pivot_inverse_t_[j].transpose() * permuted_[j];
    permuted_[j] = y;
    for (std::uint32_t q = column_start_[j]; q < column_start_[j + 1]; ++q)
      permuted_[row_of_[q]].noalias() -= factor_[q] * y;
  }
  for (std::uint32_t j = nodes_; j-- > 0;) {  // L^T x = y
    Vec3 sum = permuted_[j];
    for (std::uint32_t q = column_start_[j]; q < column_start_[j + 1]; ++q)
      sum.noalias() -= factor_[q].transpose() * permuted_[row_of_[q]];
    permuted_[j] = pivot_inverse_t_[j] * sum;
  }
  for (std::uint32_t k = 0; k < nodes_; ++k)
    Eigen::Map<Vec3>(rhs.data() + 3 * std::size_t(order_[k])) = permuted_[k];
}

}  // namespace imasim::physics
