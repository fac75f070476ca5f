#include "geometry/uniform_grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace imasim::geometry {

namespace {
constexpr int kMaxCellsPerAxis = 256;  // caps memory for large, sparse sets
}

void UniformGrid::rebuild(const std::vector<Box>& boxes, Real cell) {
  if (!(cell > 0)) throw std::invalid_argument("uniform grid cell size must be positive");
  item_count_ = boxes.size();
  Box bounds;
  for (const Box& b : boxes)
    bounds.extend(b);
  if (boxes.empty()) bounds.extend(Vec3::Zero());
  origin_ = bounds.min();
  const Vec3 extent = bounds.max() - bounds.min();
  // Grow the cell if the grid would be too fine for the extent.
  cell_ = std::max(cell, extent.maxCoeff() / Real(kMaxCellsPerAxis));
  for (int a = 0; a < 3; ++a)
    dims_[a] = std::max(1, int(std::floor(extent[a] / cell_)) + 1);
  const std::size_t cells = std::size_t(dims_[0]) * dims_[1] * dims_[2];
  start_.resize(cells + 1);
  std::fill(start_.begin(), start_.end(), 0u);
  auto for_cells = [&](const Box& b, auto&& f) {
    const auto lo = cell_of(b.min()), hi = cell_of(b.max());
    for (int z = lo[2]; z <= hi[2]; ++z)
      for (int y = lo[1]; y <= hi[1]; ++y)
        for (int x = lo[0]; x <= hi[0]; ++x)
          f(index(x, y, z));
  };
  for (const Box& b : boxes)
    for_cells(b, [&](std::size_t c) { ++start_[c + 1]; });
  for (std::size_t c = 0; c < cells; ++c)
    start_[c + 1] += start_[c];
  items_.resize(start_[cells]);
  fill_.resize(cells);
  std::copy(start_.begin(), start_.begin() + static_cast<std::ptrdiff_t>(cells), fill_.begin());
  for (std::uint32_t i = 0; i < boxes.size(); ++i) {
    for_cells(boxes[i], [&](std::size_t c) { items_[fill_[c]++] = i; });
  }
}

void UniformGrid::reserve_headroom(Real factor) {
  const auto grow = [factor](std::vector<std::uint32_t>& v) {
    v.reserve(static_cast<std::size_t>(Real(v.size()) * factor) + 8);
  };
  grow(start_);
  grow(items_);
  grow(fill_);
}

std::array<int, 3> UniformGrid::cell_of(const Vec3& p) const {
  std::array<int, 3> c;
  for (int a = 0; a < 3; ++a) {
    Real f = std::floor((p[a] - origin_[a]) / cell_);
    f = std::isfinite(f) ? std::clamp(f, Real(0), Real(dims_[a] - 1)) : Real(0);
    c[a] = int(f);
  }
  return c;
}

Box triangle_box(const Vec3& a, const Vec3& b, const Vec3& c) {
  Box box(a);
  box.extend(b);
  box.extend(c);
  return box;
}

}  // namespace imasim::geometry
