// Repairs of meshes as segmentation tools export them (geometry/mesh_repair.hpp).
#include "geometry/mesh_repair.hpp"

#include <gtest/gtest.h>

#include "geometry/mesh_checks.hpp"

namespace imasim::geometry {
namespace {

// An open tube of n segments around and two rings: a band with two boundary loops.
TriangleMesh open_band(std::uint32_t n) {
  TriangleMesh m;
  for (std::uint32_t ring = 0; ring < 2; ++ring)
    for (std::uint32_t i = 0; i < n; ++i) {
      const Real a = Real(2 * 3.14159265358979323846 * i / n);
      m.vertices.push_back(Vec3(std::cos(a), std::sin(a), Real(ring)));
    }
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    m.triangles.push_back({i, j, n + j});  // outward: counter-clockwise seen from outside
    m.triangles.push_back({i, n + j, n + i});
  }
  return m;
}

TEST(MeshRepair, CollapsedTrianglesAndTheirOrphanVerticesGo) {
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(5, 5, 5), Vec3(0, 0, 1)};
  m.triangles = {{0, 1, 2}, {3, 3, 1}, {0, 4, 1}};
  EXPECT_EQ(drop_collapsed_triangles(m), 1u);
  ASSERT_EQ(m.vertices.size(), 4u);  // vertex 3 was used only by the collapsed triangle
  EXPECT_EQ(m.vertices[3], Vec3(0, 0, 1));
  EXPECT_EQ(m.triangles[1], (Triangle{0, 3, 1}));
}

TEST(MeshRepair, AnOpenBandHasTwoLoopsAndCapsToAClosedOutwardSurface) {
  TriangleMesh m = open_band(12);
  EXPECT_NE(first_manifold_defect(m, true), "");
  const BoundaryLoops b = boundary_loops(m);
  ASSERT_EQ(b.defect, "");
  ASSERT_EQ(b.loops.size(), 2u);
  EXPECT_EQ(b.loops[0].size(), 12u);
  EXPECT_EQ(b.loops[1].size(), 12u);
  EXPECT_EQ(cap_boundary_loops(m, b), 24u);
  EXPECT_EQ(m.vertices.size(), 26u);
  EXPECT_EQ(first_mesh_defect(m, {.require_closed = true}), "");
  // A 12-gon prism of circumradius 1 and height 1: base area 12 / 2 sin(30 deg) = 3, volume 3.
  EXPECT_NEAR(enclosed_volume(m.vertices, m.triangles), 3.0, 1e-12);
  // Each cap's centre is its loop's mean (12 cosines summed: rounding of a few 1e-16).
  EXPECT_NEAR((m.vertices[24] - Vec3(0, 0, 0)).norm(), 0, 1e-14);
  EXPECT_NEAR((m.vertices[25] - Vec3(0, 0, 1)).norm(), 0, 1e-14);
}

TEST(MeshRepair, LoopsThatTouchAtAVertexCannotBeCapped) {
  // Two triangles sharing only vertex 0: their boundaries meet there.
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(-1, 0, 0), Vec3(0, -1, 0)};
  m.triangles = {{0, 1, 2}, {0, 3, 4}};
  const BoundaryLoops b = boundary_loops(m);
  EXPECT_EQ(b.defect,
            "vertex 0 is on two boundary loops (they touch there): the holes cannot be "
            "capped");
  EXPECT_TRUE(b.loops.empty());
}

TEST(MeshRepair, AClosedSurfaceHasNoBoundary) {
  TriangleMesh m = open_band(8);
  cap_boundary_loops(m, boundary_loops(m));
  const BoundaryLoops b = boundary_loops(m);
  EXPECT_EQ(b.defect, "");
  EXPECT_TRUE(b.loops.empty());
}

}  // namespace
}  // namespace imasim::geometry
