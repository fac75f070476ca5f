#include "geometry/edge_adjacency.hpp"

#include <algorithm>
#include <tuple>

namespace imasim::geometry {

std::size_t EdgeAdjacency::interior_edge_count() const {
  return static_cast<std::size_t>(
      std::count_if(edges.begin(), edges.end(), [](const MeshEdge& e) { return e.is_interior(); }));
}

namespace {

struct HalfEdge {
  std::uint32_t lo, hi;  // sorted endpoints: the key
  std::uint32_t from, to;
  std::uint32_t face, opposite;
};

}  // namespace

// Sorting half-edges (rather than hashing) keeps the result independent of hash seeds and
// platform, and is O(E log E).
EdgeAdjacency build_edge_adjacency(const TriangleMesh& mesh) {
  std::vector<HalfEdge> half;
  half.reserve(mesh.triangles.size() * 3);
  for (std::uint32_t f = 0; f < mesh.triangles.size(); ++f) {
    const Triangle& t = mesh.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t from = t[k], to = t[(k + 1) % 3], opp = t[(k + 2) % 3];
      half.push_back({std::min(from, to), std::max(from, to), from, to, f, opp});
    }
  }
  std::sort(half.begin(), half.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return std::tie(x.lo, x.hi, x.face) < std::tie(y.lo, y.hi, y.face);
  });

  EdgeAdjacency adj;
  adj.edges.reserve(half.size() / 2 + 1);
  for (std::size_t i = 0; i < half.size();) {
    std::size_t j = i;
    while (j < half.size() && half[j].lo == half[i].lo && half[j].hi == half[i].hi)
      ++j;
    const std::size_t count = j - i;
    if (count > 2) {
      adj.non_manifold_edges.push_back({half[i].lo, half[i].hi});
    } else {
      MeshEdge e;
      e.a = half[i].from;
      e.b = half[i].to;
      for (std::size_t k = 0; k < count; ++k) {
        e.faces[k] = half[i + k].face;
        e.opposite[k] = half[i + k].opposite;
      }
      adj.edges.push_back(e);
    }
    i = j;
  }
  return adj;
}

}  // namespace imasim::geometry
