#pragma once
// An indexed triangle mesh: vertex positions (unit: m) and counter-clockwise faces.
#include <array>
#include <cstdint>
#include <vector>

#include "math/types.hpp"

namespace imasim::geometry {

using Triangle = std::array<std::uint32_t, 3>;

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<Triangle> triangles;

  std::size_t vertex_count() const { return vertices.size(); }
  std::size_t triangle_count() const { return triangles.size(); }
};

}  // namespace imasim::geometry
