#include <gtest/gtest.h>

#include "geometry/edge_adjacency.hpp"
#include "geometry/tube.hpp"
#include "geometry/vertex_normals.hpp"
#include "precision.hpp"

namespace imasim::geometry {
namespace {

TEST(Tube, RingsSitOnTheRadiusAndNormalsPointOut) {
  const TriangleMesh m = make_tube({{Vec3(0, 0, 0), Vec3(0, 0, 0.1)}, 0.002, 8, 11});
  ASSERT_EQ(m.vertex_count(), 88u);
  ASSERT_EQ(m.triangle_count(), 2u * 8u * 10u);
  std::vector<Vec3> normals(m.vertex_count());
  compute_vertex_normals(m.vertices, m.triangles, normals);
  for (std::size_t i = 0; i < m.vertex_count(); ++i) {
    const Vec3 radial(m.vertices[i].x(), m.vertices[i].y(), 0);
    EXPECT_NEAR(radial.norm(), 0.002, test::ulps(8, 0.1));
    EXPECT_GT(normals[i].dot(radial), 0);
  }
  EXPECT_NEAR(m.vertices[80].z(), 0.1, test::ulps(4, 0.1));  // last ring at the end
  const EdgeAdjacency adj = build_edge_adjacency(m);
  EXPECT_TRUE(adj.non_manifold_edges.empty());
  EXPECT_EQ(adj.boundary_edge_count(), 16u);  // two open end rings
}

TEST(Tube, FollowsABentCenterlineWithoutTwisting) {
  std::vector<Vec3> c;
  for (int k = 0; k <= 20; ++k)
    c.emplace_back(0.05 * std::sin(k * 0.05), 0, 0.05 * std::cos(k * 0.05));
  const TriangleMesh m = make_tube({c, 0.001, 6, 30});
  const std::vector<Vec3> centre = resample_polyline(c, 30);
  for (std::uint32_t r = 0; r < 30; ++r) {
    for (std::uint32_t k = 0; k < 6; ++k) {
      EXPECT_NEAR((m.vertices[r * 6 + k] - centre[r]).norm(), 0.001, 1e-9);
    }
  }
}

TEST(Tube, RejectsBadSpecs) {
  EXPECT_THROW(make_tube({{Vec3::Zero(), Vec3::Zero()}, 0.001, 6, 4}), std::invalid_argument);
  EXPECT_THROW(make_tube({{Vec3::Zero(), Vec3::UnitZ()}, 0.001, 2, 4}), std::invalid_argument);
  EXPECT_THROW(make_tube({{Vec3::Zero(), Vec3::UnitZ()}, -1, 6, 4}), std::invalid_argument);
}

TEST(CylinderPatch, NormalsFaceTheAxis) {
  CylinderPatchSpec spec;
  const TriangleMesh m = make_cylinder_patch(spec);
  for (const Triangle& t : m.triangles) {
    const Vec3 n = face_normal(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]);
    Vec3 to_axis = spec.origin - m.vertices[t[0]];
    to_axis.z() = 0;
    EXPECT_GT(n.dot(to_axis), 0);
  }
}

}  // namespace
}  // namespace imasim::geometry
