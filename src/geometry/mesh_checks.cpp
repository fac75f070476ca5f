#include "geometry/mesh_checks.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "geometry/edge_adjacency.hpp"
#include "math/angles.hpp"

namespace imasim::geometry {

namespace {

std::string describe(const TriangleMesh& mesh, std::size_t t) {
  const Triangle& tri = mesh.triangles[t];
  std::ostringstream s;
  s << "triangle " << t << " (vertices " << tri[0] << ", " << tri[1] << ", " << tri[2] << ")";
  return s.str();
}

// Union-find over a small index range, with path halving.
std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

}  // namespace

Real triangle_area(const Vec3& a, const Vec3& b, const Vec3& c) {
  return Real(0.5) * (b - a).cross(c - a).norm();
}

Real smallest_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3* x[3] = {&a, &b, &c};
  Real smallest = kPi;
  for (int k = 0; k < 3; ++k) {
    const Vec3 u = *x[(k + 1) % 3] - *x[k];
    const Vec3 v = *x[(k + 2) % 3] - *x[k];
    // atan2 of |u x v| and u.v is accurate for angles near 0 and pi alike.
    smallest = std::min(smallest, std::atan2(u.cross(v).norm(), u.dot(v)));
  }
  return smallest;
}

Real triangle_area(const TriangleMesh& mesh, std::size_t t) {
  const Triangle& tri = mesh.triangles[t];
  return triangle_area(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]);
}

Real smallest_angle(const TriangleMesh& mesh, std::size_t t) {
  const Triangle& tri = mesh.triangles[t];
  return smallest_angle(mesh.vertices[tri[0]], mesh.vertices[tri[1]], mesh.vertices[tri[2]]);
}

std::string first_index_defect(const TriangleMesh& mesh, bool require_used_vertices) {
  std::vector<bool> used(mesh.vertices.size(), false);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Triangle& tri = mesh.triangles[t];
    for (std::uint32_t v : tri) {
      if (v >= mesh.vertices.size()) {
        return describe(mesh, t) + " refers to vertex " + std::to_string(v) + " of " +
               std::to_string(mesh.vertices.size());
      }
      used[v] = true;
    }
    if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2])
      return describe(mesh, t) + " repeats a vertex";
  }
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    const Vec3& x = mesh.vertices[v];
    if (!(std::isfinite(x.x()) && std::isfinite(x.y()) && std::isfinite(x.z())))
      return "vertex " + std::to_string(v) + " has a non-finite coordinate";
    if (require_used_vertices && !used[v])
      return "vertex " + std::to_string(v) + " belongs to no triangle";
  }
  return {};
}

std::string first_degenerate_triangle(const TriangleMesh& mesh, Real min_area, Real min_angle) {
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const Real area = triangle_area(mesh, t);
    if (!(area >= min_area)) {
      std::ostringstream s;
      s << describe(mesh, t) << " is degenerate: area " << area << " m^2 < " << min_area;
      return s.str();
    }
    const Real angle = smallest_angle(mesh, t);
    if (!(angle >= min_angle)) {
      std::ostringstream s;
      s << describe(mesh, t) << " is degenerate: angle " << angle << " rad < " << min_angle;
      return s.str();
    }
  }
  return {};
}

std::string first_manifold_defect(const TriangleMesh& mesh, bool require_closed) {
  // Edges in sorted (min, max) order; those in more than two triangles are set apart.
  const EdgeAdjacency adjacency = build_edge_adjacency(mesh);
  if (!adjacency.non_manifold_edges.empty()) {
    const auto& e = adjacency.non_manifold_edges.front();
    return "edge (" + std::to_string(e[0]) + ", " + std::to_string(e[1]) +
           ") is shared by more than two triangles: not a manifold";
  }
  for (const MeshEdge& e : adjacency.edges) {
    const std::string edge = "edge (" + std::to_string(std::min(e.a, e.b)) + ", " +
                             std::to_string(std::max(e.a, e.b)) + ")";
    if (!e.is_interior()) {
      if (require_closed) {
        return edge + " of triangle " + std::to_string(e.faces[0]) +
               " is on a boundary: the surface is not closed";
      }
      continue;
    }
    // The first face runs a -> b; a consistently oriented neighbour runs b -> a.
    const Triangle& t = mesh.triangles[e.faces[1]];
    for (int k = 0; k < 3; ++k) {
      if (t[k] == e.a && t[(k + 1) % 3] == e.b) {
        return edge + " runs the same way in triangles " + std::to_string(e.faces[0]) + " and " +
               std::to_string(e.faces[1]) + ": inconsistent orientation";
      }
    }
  }

  // Each vertex must be the centre of one fan: the opposite edges of its triangles (its link)
  // form one connected path or cycle.
  const std::size_t n = mesh.vertices.size();
  std::vector<std::uint32_t> start(n + 1, 0), incident(mesh.triangles.size() * 3);
  for (const Triangle& tri : mesh.triangles)
    for (std::uint32_t v : tri)
      ++start[v + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for (std::uint32_t v : mesh.triangles[t])
      incident[fill[v]++] = static_cast<std::uint32_t>(t);
  std::vector<std::uint32_t> link, parent;
  for (std::uint32_t v = 0; v < n; ++v) {
    link.clear();
    for (std::uint32_t k = start[v]; k < start[v + 1]; ++k) {
      for (std::uint32_t w : mesh.triangles[incident[k]])
        if (w != v) link.push_back(w);
    }
    std::sort(link.begin(), link.end());
    link.erase(std::unique(link.begin(), link.end()), link.end());
    parent.resize(link.size());
    std::iota(parent.begin(), parent.end(), 0u);
    auto slot = [&](std::uint32_t w) {
      return static_cast<std::uint32_t>(std::lower_bound(link.begin(), link.end(), w) -
                                        link.begin());
    };
    std::uint32_t groups = static_cast<std::uint32_t>(link.size());
    for (std::uint32_t k = start[v]; k < start[v + 1]; ++k) {
      std::uint32_t ends[2], e = 0;
      for (std::uint32_t w : mesh.triangles[incident[k]])
        if (w != v) ends[e++] = slot(w);
      const std::uint32_t ra = find_root(parent, ends[0]), rb = find_root(parent, ends[1]);
      if (ra != rb) parent[ra] = rb, --groups;
    }
    if (groups > 1) {
      return "vertex " + std::to_string(v) + " joins " + std::to_string(groups) +
             " separate fans of triangles: not a manifold";
    }
  }
  return {};
}

std::string first_mesh_defect(const TriangleMesh& mesh, const MeshCheckOptions& options) {
  if (std::string d = first_index_defect(mesh, options.require_used_vertices); !d.empty()) return d;
  if (std::string d = first_degenerate_triangle(mesh, options.min_area, options.min_angle);
      !d.empty())
    return d;
  return first_manifold_defect(mesh, options.require_closed);
}

std::uint32_t triangle_components(const TriangleMesh& mesh, std::vector<std::uint32_t>& component) {
  std::vector<std::uint32_t> parent(mesh.vertices.size());
  std::iota(parent.begin(), parent.end(), 0u);
  for (const Triangle& tri : mesh.triangles) {
    for (int k = 1; k < 3; ++k) {
      const std::uint32_t a = find_root(parent, tri[0]), b = find_root(parent, tri[k]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
  }
  // Number the components in order of their first triangle.
  std::vector<std::uint32_t> label(mesh.vertices.size(), ~0u);
  std::uint32_t count = 0;
  component.resize(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::uint32_t root = find_root(parent, mesh.triangles[t][0]);
    if (label[root] == ~0u) label[root] = count++;
    component[t] = label[root];
  }
  return count;
}

Real enclosed_volume(std::span<const Vec3> x, std::span<const Triangle> triangles) {
  Real six_volume = 0;  // sum of a . (b x c) over the triangles = 6 V
  for (const Triangle& t : triangles)
    six_volume += x[t[0]].dot(x[t[1]].cross(x[t[2]]));
  return six_volume / 6;
}

}  // namespace imasim::geometry
