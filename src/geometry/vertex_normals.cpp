#include "geometry/vertex_normals.hpp"

namespace imasim::geometry {

void compute_vertex_normals(std::span<const Vec3> positions, std::span<const Triangle> triangles,
                            std::span<Vec3> normals) {
  for (Vec3& n : normals)
    n.setZero();
  for (const Triangle& t : triangles) {
    const Vec3 n = face_normal(positions[t[0]], positions[t[1]], positions[t[2]]);
    for (std::uint32_t v : t)
      normals[v] += n;
  }
  for (Vec3& n : normals) {
    const Real len = n.norm();
    if (len > 0) n /= len;
  }
}

}  // namespace imasim::geometry
