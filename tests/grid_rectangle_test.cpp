#include <gtest/gtest.h>

#include "precision.hpp"

#include <stdexcept>

#include "geometry/grid_rectangle.hpp"

namespace imasim::geometry {
namespace {

TEST(GridRectangle, PlacesVerticesOnTheGrid) {
  const TriangleMesh m = make_grid_rectangle({2.0, 3.0, 5, 4});
  ASSERT_EQ(m.vertex_count(), 20u);
  ASSERT_EQ(m.triangle_count(), 2u * 4u * 3u);
  EXPECT_EQ(m.vertices[grid_index(4, 3, 5)], Vec3(2.0, 0.0, 3.0));
  EXPECT_EQ(m.vertices[grid_index(1, 2, 5)], Vec3(0.5, 0.0, 2.0));
}

TEST(GridRectangle, NormalsPointUpAndAreaAddsUp) {
  const TriangleMesh m = make_grid_rectangle({2.0, 3.0, 7, 6});
  double area = 0;
  for (const Triangle& t : m.triangles) {
    const Vec3 n = (m.vertices[t[1]] - m.vertices[t[0]]).cross(m.vertices[t[2]] - m.vertices[t[0]]);
    EXPECT_GT(n.y(), 0);
    area += 0.5 * n.norm();
  }
  EXPECT_NEAR(area, 6.0, test::ulps(4, 6.0));
}

TEST(GridRectangle, AlternatesTheDiagonals) {
  // Cell (0,0) (i + j even) holds the diagonal (0,0)-(1,1); cell (1,0) holds (2,0)-(1,1).
  const std::uint32_t nx = 4;
  const TriangleMesh m = make_grid_rectangle({1.0, 1.0, nx, nx});
  auto has_edge = [&](std::uint32_t a, std::uint32_t b) {
    for (const Triangle& t : m.triangles) {
      int hits = 0;
      for (std::uint32_t v : t)
        hits += (v == a || v == b) ? 1 : 0;
      if (hits == 2) return true;
    }
    return false;
  };
  EXPECT_TRUE(has_edge(grid_index(0, 0, nx), grid_index(1, 1, nx)));
  EXPECT_FALSE(has_edge(grid_index(1, 0, nx), grid_index(0, 1, nx)));
  EXPECT_TRUE(has_edge(grid_index(2, 0, nx), grid_index(1, 1, nx)));
  EXPECT_FALSE(has_edge(grid_index(1, 0, nx), grid_index(2, 1, nx)));
}

TEST(GridRectangle, RejectsBadSizes) {
  EXPECT_THROW(make_grid_rectangle({1.0, 1.0, 1, 4}), std::invalid_argument);
  EXPECT_THROW(make_grid_rectangle({0.0, 1.0, 3, 4}), std::invalid_argument);
  EXPECT_THROW(make_grid_rectangle({1.0, -1.0, 3, 4}), std::invalid_argument);
}

}  // namespace
}  // namespace imasim::geometry
