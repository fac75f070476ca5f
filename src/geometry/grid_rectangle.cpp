#include "geometry/grid_rectangle.hpp"

#include <stdexcept>
#include <string>

namespace imasim::geometry {

TriangleMesh make_grid_rectangle(const GridRectangle& spec) {
  if (spec.nx < 2 || spec.ny < 2) {
    throw std::invalid_argument("grid rectangle needs at least 2 x 2 vertices, got " +
                                std::to_string(spec.nx) + " x " + std::to_string(spec.ny));
  }
  if (!(spec.width > 0) || !(spec.height > 0)) {
    throw std::invalid_argument("grid rectangle needs a positive width and height");
  }
  TriangleMesh mesh;
  mesh.vertices.reserve(std::size_t(spec.nx) * spec.ny);
  const Real dx = spec.width / Real(spec.nx - 1);
  const Real dz = spec.height / Real(spec.ny - 1);
  for (std::uint32_t j = 0; j < spec.ny; ++j) {
    for (std::uint32_t i = 0; i < spec.nx; ++i) {
      mesh.vertices.emplace_back(Real(i) * dx, Real(0), Real(j) * dz);
    }
  }
  mesh.triangles.reserve(std::size_t(spec.nx - 1) * (spec.ny - 1) * 2);
  for (std::uint32_t j = 0; j + 1 < spec.ny; ++j) {
    for (std::uint32_t i = 0; i + 1 < spec.nx; ++i) {
      const std::uint32_t v00 = grid_index(i, j, spec.nx), v10 = grid_index(i + 1, j, spec.nx);
      const std::uint32_t v01 = grid_index(i, j + 1, spec.nx);
      const std::uint32_t v11 = grid_index(i + 1, j + 1, spec.nx);
      // Each face (a, b, c) is wound so that (b - a) x (c - a) points along +y.
      if ((i + j) % 2 == 0) {
        mesh.triangles.push_back({v00, v11, v10});
        mesh.triangles.push_back({v00, v01, v11});
      } else {
        mesh.triangles.push_back({v00, v01, v10});
        mesh.triangles.push_back({v10, v01, v11});
      }
    }
  }
  return mesh;
}

}  // namespace imasim::geometry
