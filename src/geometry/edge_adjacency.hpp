#pragma once
// Edge -> face adjacency of a triangle mesh: the unique edges, and for each edge the faces that
// share it with the vertex opposite the edge in each face. Interior edges (two faces) carry the
// dihedral (bending) constraints; boundary edges have one face.
#include <cstdint>
#include <vector>

#include "geometry/triangle_mesh.hpp"

namespace imasim::geometry {

inline constexpr std::uint32_t kNoFace = 0xffffffffu;

struct MeshEdge {
  // Endpoints in the direction the first face traverses them (first face's winding order).
  std::uint32_t a = 0;
  std::uint32_t b = 0;
  std::uint32_t faces[2] = {kNoFace, kNoFace};
  std::uint32_t opposite[2] = {kNoFace, kNoFace};  // vertex opposite the edge in faces[k]

  bool is_interior() const { return faces[1] != kNoFace; }
};

struct EdgeAdjacency {
  std::vector<MeshEdge> edges;  // sorted by (min(a,b), max(a,b))
  // Edges shared by more than two faces: such a mesh is not a manifold. They are listed here and
  // left out of `edges`, so callers can refuse the mesh with a clear message.
  std::vector<std::array<std::uint32_t, 2>> non_manifold_edges;

  std::size_t interior_edge_count() const;
  std::size_t boundary_edge_count() const { return edges.size() - interior_edge_count(); }
};

EdgeAdjacency build_edge_adjacency(const TriangleMesh& mesh);

}  // namespace imasim::geometry
