#pragma once
// Sparse Cholesky, A = L L^T, of a symmetric positive definite matrix made of 3 x 3 blocks: one
// block row per vertex (or body) of a mesh's Newton system, the pattern the mesh's adjacency.
// Why not Eigen's SimplicialLDLT on the scalar matrix: it pays an index lookup per scalar
// multiply-add, where a block pays one per 27. On the fascia's Hessian (484 vertices, its
// hinges, a tool's body) it factors 3.6-4.1 times faster (docs/PERFORMANCE.md,
// BM_MembraneFactor). The ordering is Eigen's approximate minimum degree on the block graph.
//
// Up-looking (each row of L a sparse triangular solve over the elimination tree, as in Davis's
// CSparse): serial and fixed in its order, so its results repeat bit for bit. analyse() sizes
// everything; factorize() and solve() allocate nothing.
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "math/types.hpp"

namespace imasim::physics {

class BlockCholesky {
 public:
  using Pair = std::pair<std::uint32_t, std::uint32_t>;

  // The pattern: nodes block rows and the off-diagonal blocks pairs[s] = (a, b), a != b, each
  // unordered pair once (a block (a, b) and its transpose (b, a) are one entry). Throws
  // std::invalid_argument for a node out of range, a pair on the diagonal or named twice.
  void analyse(std::uint32_t nodes, std::span<const Pair> pairs);

  // Factors the matrix whose diagonal blocks are diagonal[a] and whose block (a, b) of pairs[s]
  // is off_diagonal[s] (and (b, a) its transpose). Symmetric: only the lower triangle of each
  // diagonal block is read. False when the matrix is not positive definite (a pivot block fails
  // its own Cholesky); the factor is then unusable until the next success.
  bool factorize(std::span<const Mat3> diagonal, std::span<const Mat3> off_diagonal);

  // rhs (3 per node) becomes A^-1 rhs. Needs a successful factorize().
  void solve(std::span<Real> rhs) const;

  std::uint32_t nodes() const { return nodes_; }
  // Blocks of L below its diagonal: its fill, the factorisation's cost.
  std::size_t factor_blocks() const { return row_of_.size(); }

 private:
  struct Entry {  // a block of A in row k, column j < k of the ordering, as stored
    std::uint32_t column = 0;
    std::uint32_t slot = 0;
    bool transposed = false;  // the stored block is A(j, k): use its transpose
  };

  std::uint32_t nodes_ = 0;
  std::vector<std::uint32_t> order_;        // order_[k]: the node eliminated k-th
  std::vector<std::uint32_t> parent_;       // the elimination tree (0xffffffff: a root)
  std::vector<std::uint32_t> entry_start_;  // row k's entries of A: entries_[start[k], start[k+1])
  std::vector<Entry> entries_;
  std::vector<std::uint32_t> column_start_;  // column j of L below the diagonal
  std::vector<std::uint32_t> row_of_;        // per block of L: its row
  std::vector<Mat3> factor_;                 // per block of L
  std::vector<Mat3> pivot_inverse_t_;        // per column: L_jj^-T
  std::vector<Mat3> pivot_;                  // per column: L_jj (lower)
  // Work space of factorize() and solve().
  mutable std::vector<std::uint32_t> filled_, mark_, stack_;
  mutable std::vector<Mat3> row_;
  mutable std::vector<Vec3> permuted_;
};

}  // namespace imasim::physics
