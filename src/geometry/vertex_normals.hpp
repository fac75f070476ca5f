#pragma once
// Area-weighted vertex normals of a triangle mesh, written into a caller-sized array so that a
// per-step update does not allocate.
#include <span>

#include "geometry/triangle_mesh.hpp"

namespace imasim::geometry {

// normals.size() must equal positions.size(); a vertex on no face gets the zero vector.
void compute_vertex_normals(std::span<const Vec3> positions, std::span<const Triangle> triangles,
                            std::span<Vec3> normals);

inline Vec3 face_normal(const Vec3& a, const Vec3& b, const Vec3& c) {
  return (b - a).cross(c - a);  // length = twice the area
}

}  // namespace imasim::geometry
