#include "geometry/surface_binding.hpp"

#include <limits>
#include <stdexcept>
#include <string>

#include "geometry/closest_point.hpp"
#include "geometry/uniform_grid.hpp"
#include "geometry/vertex_normals.hpp"

#include <Eigen/LU>

namespace imasim::geometry {

std::vector<SurfaceBinding> bind_to_surface(std::span<const Vec3> points,
                                            const TriangleMesh& surface, Real search_radius) {
  std::vector<Box> boxes;
  boxes.reserve(surface.triangles.size());
  Real mean_edge = 0;
  for (const Triangle& t : surface.triangles) {
    const Vec3 &a = surface.vertices[t[0]], &b = surface.vertices[t[1]],
               &c = surface.vertices[t[2]];
    boxes.push_back(triangle_box(a, b, c));
    mean_edge += (b - a).norm();
  }
  if (boxes.empty()) throw std::invalid_argument("cannot bind to a surface with no triangle");
  mean_edge /= Real(boxes.size());
  const UniformGrid grid(boxes, std::max(mean_edge, search_radius / 4));

  std::vector<Vec3> normals(surface.vertices.size());
  compute_vertex_normals(surface.vertices, surface.triangles, normals);

  std::vector<SurfaceBinding> out;
  out.reserve(points.size());
  std::vector<std::uint32_t> visited;
  std::uint32_t stamp = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3& p = points[i];
    const Vec3 r = Vec3::Constant(search_radius);
    Real best = std::numeric_limits<Real>::infinity();
    SurfaceBinding binding;
    // Ties go to the lowest triangle index, so the result does not depend on the grid.
    grid.visit(Box(p - r, p + r), visited, stamp, [&](std::uint32_t t) {
      const Triangle& tri = surface.triangles[t];
      const TrianglePoint q = closest_point_on_triangle(
          p, surface.vertices[tri[0]], surface.vertices[tri[1]], surface.vertices[tri[2]]);
      if (q.distance2 < best || (q.distance2 == best && t < binding.triangle)) {
        best = q.distance2;
        binding.triangle = t;
        binding.bary = q.bary;
      }
    });
    if (!(best <= search_radius * search_radius)) {
      throw std::invalid_argument("point " + std::to_string(i) + " is farther than " +
                                  std::to_string(search_radius) + " m from the surface");
    }
    // Solve p = sum b_k p_k + d sum b_k n_k for (b1, b2, d) by Newton from the closest point.
    const Triangle& tri = surface.triangles[binding.triangle];
    const Vec3 &p0 = surface.vertices[tri[0]], &p1 = surface.vertices[tri[1]],
               &p2 = surface.vertices[tri[2]];
    const Vec3 &n0 = normals[tri[0]], &n1 = normals[tri[1]], &n2 = normals[tri[2]];
    Real b1 = binding.bary[1], b2 = binding.bary[2];
    Vec3 n = (1 - b1 - b2) * n0 + b1 * n1 + b2 * n2;
    Real d = n.squaredNorm() > 0
                 ? (p - (p0 + b1 * (p1 - p0) + b2 * (p2 - p0))).dot(n) / n.squaredNorm()
                 : Real(0);
    for (int it = 0; it < 20; ++it) {
      n = (1 - b1 - b2) * n0 + b1 * n1 + b2 * n2;
      const Vec3 residual = p0 + b1 * (p1 - p0) + b2 * (p2 - p0) + d * n - p;
      if (residual.norm() <= Real(1e-15) * (1 + p.norm())) break;
      Mat3 jacobian;
      jacobian.col(0) = (p1 - p0) + d * (n1 - n0);
      jacobian.col(1) = (p2 - p0) + d * (n2 - n0);
      jacobian.col(2) = n;
      const Vec3 step = jacobian.fullPivLu().solve(residual);
      if (!step.allFinite()) break;
      b1 -= step[0];
      b2 -= step[1];
      d -= step[2];
    }
    binding.bary = {1 - b1 - b2, b1, b2};
    binding.offset = d;
    out.push_back(binding);
  }
  return out;
}

Vec3 bound_point(const SurfaceBinding& b, std::span<const Vec3> positions,
                 std::span<const Vec3> normals, std::span<const Triangle> triangles) {
  const Triangle& t = triangles[b.triangle];
  const Vec3 p =
      b.bary[0] * positions[t[0]] + b.bary[1] * positions[t[1]] + b.bary[2] * positions[t[2]];
  if (b.offset == 0) return p;
  return p + b.offset * (b.bary[0] * normals[t[0]] + b.bary[1] * normals[t[1]] +
                         b.bary[2] * normals[t[2]]);
}

void apply_bindings(std::span<const SurfaceBinding> bindings, std::span<const Vec3> positions,
                    std::span<const Vec3> normals, std::span<const Triangle> triangles,
                    std::span<Vec3> out) {
  for (std::size_t i = 0; i < bindings.size(); ++i) {
    out[i] = bound_point(bindings[i], positions, normals, triangles);
  }
}

}  // namespace imasim::geometry
