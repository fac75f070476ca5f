#pragma once
// Repairs for surface meshes as segmentation tools export them (a cardiac atlas's left ventricle:
// a structured grid whose apex pole repeats one position along a whole row, open at the valve
// plane). Welding by position collapses the pole's triangles to zero area: they are dropped.
// An open surface is closed by capping each boundary loop with a fan around its centroid, as
// mesh tools' "close holes" does. The steps are split so that a series of meshes with one
// topology (heart phases) is repaired identically: find on one mesh, apply to each.
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/triangle_mesh.hpp"

namespace imasim::geometry {

// Removes the triangles that use a vertex twice (no area by construction) and then the
// vertices no triangle uses, renumbering the rest in order. Returns the triangles removed.
std::size_t drop_collapsed_triangles(TriangleMesh& mesh);

// The boundary of a mesh as closed loops of vertices, each in the direction of its triangles'
// edges (an edge a -> b of a triangle with no triangle using b -> a). `defect` is set, and
// `loops` left empty, when the boundary is not a set of simple loops (a vertex where two
// boundary loops touch, an edge used by more than two triangles).
struct BoundaryLoops {
  std::vector<std::vector<std::uint32_t>> loops;
  std::string defect;
};
BoundaryLoops boundary_loops(const TriangleMesh& mesh);

// Closes each loop with a new vertex at the mean of the loop's vertices and one triangle per
// loop edge, oriented with the surface (for loop edge a -> b, the triangle (b, a, centre)).
// Returns the triangles added. Applied to meshes of one topology, it adds the same vertices and
// triangles to each.
std::size_t cap_boundary_loops(TriangleMesh& mesh, const BoundaryLoops& boundary);

}  // namespace imasim::geometry
