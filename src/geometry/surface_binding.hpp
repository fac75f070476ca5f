#pragma once
// Binding of points to a (coarse) triangle surface: each point is bound once to its closest
// triangle by barycentric coordinates b plus an offset d along the interpolated vertex normal,
// and is rebuilt from that triangle's current vertices p_k and unit vertex normals n_k:
//   x = sum_k b_k p_k + d * sum_k b_k n_k.
// (b, d) solve that equation for the point at binding time (Newton from the closest point), so
// the rest shape is reproduced exactly and a rigid motion of the surface moves the bound points
// rigidly. Used for the vessel's fine
// visual mesh over its coarse simulation mesh, and for strand ends on their surfaces.
#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "geometry/triangle_mesh.hpp"

namespace imasim::geometry {

struct SurfaceBinding {
  std::uint32_t triangle = 0;
  std::array<Real, 3> bary = {1, 0, 0};
  Real offset = 0;  // along the interpolated normal (unit: m)
};

// Binds each point to the closest triangle of `surface` (spatial grid; no all-pairs scan).
// `search_radius` (unit: m) bounds the search; a point farther than that from every triangle
// throws std::invalid_argument.
std::vector<SurfaceBinding> bind_to_surface(std::span<const Vec3> points,
                                            const TriangleMesh& surface, Real search_radius);

// The bound point on the surface whose vertices are at `positions` with vertex normals
// `normals` (unit length; see vertex_normals.hpp).
Vec3 bound_point(const SurfaceBinding& b, std::span<const Vec3> positions,
                 std::span<const Vec3> normals, std::span<const Triangle> triangles);

// Rebuilds every bound point into `out` (out.size() == bindings.size()); allocation-free.
void apply_bindings(std::span<const SurfaceBinding> bindings, std::span<const Vec3> positions,
                    std::span<const Vec3> normals, std::span<const Triangle> triangles,
                    std::span<Vec3> out);

}  // namespace imasim::geometry
