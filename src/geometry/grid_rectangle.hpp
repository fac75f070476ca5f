#pragma once
// Generator for a rectangular membrane: [0, width] x [0, height] sampled on an nx x ny vertex
// grid in the x-z plane (y = 0). Vertex (i, j) sits at (i*width/(nx-1), 0, j*height/(ny-1))
// and has index j*nx + i. Cell (i, j) is split along (i, j)-(i+1, j+1) when i + j is even,
// else along (i+1, j)-(i, j+1), so the diagonals alternate and the mesh has no preferred
// shear direction. Faces are wound so that their normals point along +y.
#include <cstdint>

#include "geometry/triangle_mesh.hpp"

namespace imasim::geometry {

struct GridRectangle {
  Real width = 1;   // (unit: m) extent along x
  Real height = 1;  // (unit: m) extent along z
  std::uint32_t nx = 2;
  std::uint32_t ny = 2;
};

// Throws std::invalid_argument for nx or ny below 2 or a non-positive extent.
TriangleMesh make_grid_rectangle(const GridRectangle& spec);

inline std::uint32_t grid_index(std::uint32_t i, std::uint32_t j, std::uint32_t nx) {
  return j * nx + i;
}

}  // namespace imasim::geometry
