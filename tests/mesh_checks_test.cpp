// Mesh soundness checks: each defect is found and named; sound meshes pass.
#include "geometry/mesh_checks.hpp"

#include <gtest/gtest.h>

#include "geometry/grid_rectangle.hpp"

namespace imasim::geometry {
namespace {

// A closed, outward-oriented tetrahedron with edges 1 along the axes.
TriangleMesh tetrahedron() {
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, 0, 1)};
  m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  return m;
}

TEST(MeshChecks, SoundClosedMeshPasses) {
  MeshCheckOptions closed;
  closed.require_closed = true;
  EXPECT_EQ(first_mesh_defect(tetrahedron(), closed), "");
}

TEST(MeshChecks, VolumeOfTetrahedronIsOneSixth) {
  const TriangleMesh m = tetrahedron();
  EXPECT_DOUBLE_EQ(enclosed_volume(m.vertices, m.triangles), 1.0 / 6.0);
}

TEST(MeshChecks, OpenSurfaceFailsOnlyWhenClosedIsRequired) {
  TriangleMesh m = tetrahedron();
  m.triangles.pop_back();
  EXPECT_EQ(first_mesh_defect(m), "");
  MeshCheckOptions closed;
  closed.require_closed = true;
  EXPECT_NE(first_mesh_defect(m, closed).find("not closed"), std::string::npos);
}

TEST(MeshChecks, EdgeSharedByThreeTrianglesIsNotAManifold) {
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(0, 0, 1)};
  m.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  const std::string d = first_mesh_defect(m);
  EXPECT_NE(d.find("edge (0, 1) is shared by more than two triangles"), std::string::npos) << d;
}

TEST(MeshChecks, FlippedTriangleIsInconsistentOrientation) {
  TriangleMesh m = tetrahedron();
  std::swap(m.triangles[3][1], m.triangles[3][2]);
  const std::string d = first_mesh_defect(m);
  EXPECT_NE(d.find("inconsistent orientation"), std::string::npos) << d;
}

TEST(MeshChecks, TwoFansMeetingAtAVertexIsNotAManifold) {
  // A bow tie: two triangles touching only at vertex 0.
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(1, 1, 0), Vec3(-1, 0, 0), Vec3(-1, -1, 0)};
  m.triangles = {{0, 1, 2}, {0, 3, 4}};
  const std::string d = first_mesh_defect(m);
  EXPECT_NE(d.find("vertex 0 joins 2 separate fans"), std::string::npos) << d;
}

TEST(MeshChecks, ZeroAreaAndSliverTrianglesAreDegenerate) {
  TriangleMesh m;
  m.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(2, 0, 0)};
  m.triangles = {{0, 1, 2}};
  EXPECT_NE(first_mesh_defect(m).find("triangle 0 (vertices 0, 1, 2) is degenerate: area"),
            std::string::npos);
  // Area 5e-5 m^2 passes the area bound; its smallest angle, about 1e-4 rad, does not.
  m.vertices[2] = Vec3(0.5, 1e-4, 0);
  const std::string d = first_mesh_defect(m);
  EXPECT_NE(d.find("is degenerate: angle"), std::string::npos) << d;
  EXPECT_NEAR(smallest_angle(m, 0), std::atan(2e-4), 1e-12);
}

TEST(MeshChecks, IndexProblemsAreNamed) {
  TriangleMesh m = tetrahedron();
  m.triangles[1][2] = 9;
  EXPECT_NE(first_mesh_defect(m).find("triangle 1 (vertices 0, 1, 9) refers to vertex 9 of 4"),
            std::string::npos);
  m = tetrahedron();
  m.triangles[2] = {0, 3, 3};
  EXPECT_NE(first_mesh_defect(m).find("repeats a vertex"), std::string::npos);
  m = tetrahedron();
  m.vertices.push_back(Vec3(5, 5, 5));
  EXPECT_NE(first_mesh_defect(m).find("vertex 4 belongs to no triangle"), std::string::npos);
  m = tetrahedron();
  m.vertices[2].y() = std::numeric_limits<Real>::quiet_NaN();
  EXPECT_NE(first_mesh_defect(m).find("vertex 2 has a non-finite coordinate"), std::string::npos);
}

TEST(MeshChecks, ComponentsAreNumberedInOrderOfFirstTriangle) {
  TriangleMesh m = tetrahedron();
  const TriangleMesh second = tetrahedron();
  for (const Vec3& v : second.vertices)
    m.vertices.push_back(v + Vec3(3, 0, 0));
  for (const Triangle& t : second.triangles)
    m.triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
  std::swap(m.triangles[0], m.triangles[5]);
  std::vector<std::uint32_t> component;
  ASSERT_EQ(triangle_components(m, component), 2u);
  EXPECT_EQ(component, (std::vector<std::uint32_t>{0, 1, 1, 1, 0, 1, 0, 0}));
}

TEST(MeshChecks, RegularGridIsAnOpenManifold) {
  const TriangleMesh grid = make_grid_rectangle({0.1, 0.1, 7, 5});
  EXPECT_EQ(first_mesh_defect(grid), "");
}

}  // namespace
}  // namespace imasim::geometry
