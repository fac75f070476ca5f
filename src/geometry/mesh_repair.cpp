#include "geometry/mesh_repair.hpp"

#include <algorithm>
#include <map>
#include <utility>

namespace imasim::geometry {

std::size_t drop_collapsed_triangles(TriangleMesh& mesh) {
  const std::size_t before = mesh.triangles.size();
  std::erase_if(mesh.triangles,
                [](const Triangle& t) { return t[0] == t[1] || t[1] == t[2] || t[0] == t[2]; });
  constexpr std::uint32_t kUnused = ~0u;
  std::vector<std::uint32_t> renumber(mesh.vertices.size(), kUnused);
  for (const Triangle& t : mesh.triangles)
    for (std::uint32_t v : t)
      if (v < renumber.size()) renumber[v] = 0;
  std::vector<Vec3> kept;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if (renumber[v] == kUnused) continue;
    renumber[v] = static_cast<std::uint32_t>(kept.size());
    kept.push_back(mesh.vertices[v]);
  }
  for (Triangle& t : mesh.triangles)
    for (std::uint32_t& v : t)
      if (v < renumber.size()) v = renumber[v];
  mesh.vertices = std::move(kept);
  return before - mesh.triangles.size();
}

BoundaryLoops boundary_loops(const TriangleMesh& mesh) {
  BoundaryLoops out;
  // Directed edges and how often each is used.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      ++uses[{t[k], t[(k + 1) % 3]}];
  std::map<std::uint32_t, std::uint32_t> next;  // boundary edge a -> b, by a
  for (const auto& [edge, count] : uses) {
    const auto [a, b] = edge;
    const auto reverse = uses.find({b, a});
    const int opposite = reverse == uses.end() ? 0 : reverse->second;
    if (count > 1 || opposite > 1) {
      out.defect = "edge (" + std::to_string(std::min(a, b)) + ", " +
                   std::to_string(std::max(a, b)) + ") is used by more than two triangles";
      return out;
    }
    if (opposite == 1) continue;
    if (!next.emplace(a, b).second) {
      out.defect = "vertex " + std::to_string(a) +
                   " is on two boundary loops (they touch there): the holes cannot be capped";
      return out;
    }
  }
  // Follow each loop from its smallest vertex (deterministic order).
  std::map<std::uint32_t, bool> visited;
  for (const auto& [start, unused] : next) {
    if (visited[start]) continue;
    std::vector<std::uint32_t> loop;
    std::uint32_t v = start;
    while (!visited[v]) {
      visited[v] = true;
      loop.push_back(v);
      const auto it = next.find(v);
      if (it == next.end()) {
        out.defect = "the boundary through vertex " + std::to_string(v) + " does not close";
        out.loops.clear();
        return out;
      }
      v = it->second;
    }
    if (v != start) {
      out.defect = "the boundary through vertex " + std::to_string(v) + " is not a simple loop";
      out.loops.clear();
      return out;
    }
    out.loops.push_back(std::move(loop));
  }
  return out;
}

std::size_t cap_boundary_loops(TriangleMesh& mesh, const BoundaryLoops& boundary) {
  std::size_t added = 0;
  for (const std::vector<std::uint32_t>& loop : boundary.loops) {
    Vec3 centre = Vec3::Zero();
    for (std::uint32_t v : loop)
      centre += mesh.vertices[v];
    centre /= Real(loop.size());
    const auto c = static_cast<std::uint32_t>(mesh.vertices.size());
    mesh.vertices.push_back(centre);
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const std::uint32_t a = loop[k], b = loop[(k + 1) % loop.size()];
      mesh.triangles.push_back({b, a, c});
      ++added;
    }
  }
  return added;
}

}  // namespace imasim::geometry
