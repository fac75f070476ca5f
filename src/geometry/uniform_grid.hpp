#pragma once
// A uniform grid over axis-aligned boxes (of triangles, points, segments): each cell lists the
// items whose box overlaps it. Built once at set-up; queries visit the items in the cells a box
// overlaps. This is the spatial structure behind closest-point and ray queries at set-up
// (strand generation, surface binding, coupling maps), so none of them scans all items.
#include <cstdint>
#include <vector>

#include <Eigen/Geometry>

#include "math/types.hpp"

namespace imasim::geometry {

using Box = Eigen::AlignedBox<Real, 3>;

class UniformGrid {
 public:
  UniformGrid() = default;
  // `cell` (unit: m) > 0; boxes may be empty-volume (points).
  UniformGrid(const std::vector<Box>& boxes, Real cell) { rebuild(boxes, cell); }

  // Rebuilds over new boxes, reusing the storage: no allocation once it has grown to the sizes
  // needed (for a moving surface rebuilt every step).
  void rebuild(const std::vector<Box>& boxes, Real cell);

  // Calls f(item) once for each item whose box overlaps cells touched by `query`. `visited` is a
  // caller-owned stamp array (one entry per item, kept between calls) used to report each
  // item once.
  template <class F>
  void visit(const Box& query, std::vector<std::uint32_t>& visited, std::uint32_t& stamp,
             const F& f) const {
    if (visited.size() < item_count_) visited.assign(item_count_, 0u);
    ++stamp;
    const auto lo = cell_of(query.min()), hi = cell_of(query.max());
    for (int z = lo[2]; z <= hi[2]; ++z) {
      for (int y = lo[1]; y <= hi[1]; ++y) {
        for (int x = lo[0]; x <= hi[0]; ++x) {
          const std::size_t c = index(x, y, z);
          for (std::uint32_t k = start_[c]; k < start_[c + 1]; ++k) {
            const std::uint32_t item = items_[k];
            if (visited[item] == stamp) continue;
            visited[item] = stamp;
            f(item);
          }
        }
      }
    }
  }

  Real cell_size() const { return cell_; }

  // Reserves `factor` times the current storage, so that rebuilds over boxes that move and
  // change their extent (a beating heart) stay allocation-free.
  void reserve_headroom(Real factor);

 private:
  std::array<int, 3> cell_of(const Vec3& p) const;
  std::size_t index(int x, int y, int z) const {
    return (std::size_t(z) * std::size_t(dims_[1]) + std::size_t(y)) * std::size_t(dims_[0]) +
           std::size_t(x);
  }

  Vec3 origin_ = Vec3::Zero();
  Real cell_ = 1;
  std::array<int, 3> dims_ = {1, 1, 1};
  std::vector<std::uint32_t> start_;  // CSR: items of cell c are items_[start_[c] .. start_[c+1])
  std::vector<std::uint32_t> items_;
  std::vector<std::uint32_t> fill_;  // build scratch
  std::size_t item_count_ = 0;
};

// Box of a triangle of `vertices`.
Box triangle_box(const Vec3& a, const Vec3& b, const Vec3& c);

}  // namespace imasim::geometry
