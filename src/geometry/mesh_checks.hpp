#pragma once
// Soundness checks of a triangle mesh, shared by mesh loading and topology changes (cutting):
// indices in range, no degenerate triangle (area or smallest angle below a bound), every edge
// used by at most two triangles with opposite directions (a consistently oriented 2-manifold),
// every vertex a single fan of triangles, and, on request, no boundary (a closed surface).
// Each check returns a description of the first defect found, or an empty string.
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "geometry/triangle_mesh.hpp"

namespace imasim::geometry {

struct MeshCheckOptions {
  Real min_area = Real(1e-14);        // smallest triangle area accepted (unit: m^2)
  Real min_angle = Real(1e-3);        // smallest interior angle accepted (unit: rad)
  bool require_closed = false;        // every edge shared by exactly two triangles
  bool require_used_vertices = true;  // no vertex outside every triangle
};

// "" when the mesh passes every check, else the first defect, e.g. "triangle 12 (vertices 3,
// 4, 9) is degenerate: area 0 m^2".
std::string first_mesh_defect(const TriangleMesh& mesh, const MeshCheckOptions& options = {});

// Individual checks, in the order first_mesh_defect applies them.
std::string first_index_defect(const TriangleMesh& mesh, bool require_used_vertices);
std::string first_degenerate_triangle(const TriangleMesh& mesh, Real min_area, Real min_angle);
std::string first_manifold_defect(const TriangleMesh& mesh, bool require_closed);

// Smallest interior angle of triangle t (unit: rad) and its area (unit: m^2).
Real smallest_angle(const TriangleMesh& mesh, std::size_t t);
Real triangle_area(const TriangleMesh& mesh, std::size_t t);
Real smallest_angle(const Vec3& a, const Vec3& b, const Vec3& c);
Real triangle_area(const Vec3& a, const Vec3& b, const Vec3& c);

// Connected components over shared vertices: component index per triangle; returns the count.
std::uint32_t triangle_components(const TriangleMesh& mesh, std::vector<std::uint32_t>& component);

// Volume enclosed by a closed, outward-oriented surface (negative if it faces inwards),
// by the divergence theorem over the given triangles (unit: m^3).
Real enclosed_volume(std::span<const Vec3> vertices, std::span<const Triangle> triangles);

}  // namespace imasim::geometry
