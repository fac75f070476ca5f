#include <gtest/gtest.h>

#include "geometry/edge_adjacency.hpp"
#include "geometry/grid_rectangle.hpp"

namespace imasim::geometry {
namespace {

TEST(EdgeAdjacency, CountsEdgesOfAGrid) {
  const std::uint32_t n = 9;
  const EdgeAdjacency adj = build_edge_adjacency(make_grid_rectangle({1.0, 1.0, n, n}));
  const std::size_t cells = (n - 1) * (n - 1);
  EXPECT_EQ(adj.edges.size(), 2 * n * (n - 1) + cells);  // rows + columns + one diagonal per cell
  EXPECT_EQ(adj.boundary_edge_count(), 4 * (n - 1));
  EXPECT_TRUE(adj.non_manifold_edges.empty());
}

TEST(EdgeAdjacency, RecordsFacesAndOppositeVertices) {
  // Two triangles sharing edge 1-2: (0, 1, 2) and (2, 1, 3).
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0)};
  m.triangles = {{0, 1, 2}, {2, 1, 3}};
  const EdgeAdjacency adj = build_edge_adjacency(m);
  ASSERT_EQ(adj.edges.size(), 5u);
  int interior = 0;
  for (const MeshEdge& e : adj.edges) {
    if (!e.is_interior()) continue;
    ++interior;
    EXPECT_EQ(e.a, 1u);  // face 0 traverses 1 -> 2
    EXPECT_EQ(e.b, 2u);
    EXPECT_EQ(e.faces[0], 0u);
    EXPECT_EQ(e.opposite[0], 0u);
    EXPECT_EQ(e.faces[1], 1u);
    EXPECT_EQ(e.opposite[1], 3u);
  }
  EXPECT_EQ(interior, 1);
}

TEST(EdgeAdjacency, ReportsNonManifoldEdges) {
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1)};
  m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};  // edge 0-1 in three faces
  const EdgeAdjacency adj = build_edge_adjacency(m);
  ASSERT_EQ(adj.non_manifold_edges.size(), 1u);
  EXPECT_EQ(adj.non_manifold_edges[0][0], 0u);
  EXPECT_EQ(adj.non_manifold_edges[0][1], 1u);
}

}  // namespace
}  // namespace imasim::geometry
