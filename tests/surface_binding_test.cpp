// Coarse-to-fine surface mapping: exact under rigid motion, close under bending.
#include <gtest/gtest.h>

#include "geometry/closest_point.hpp"
#include "geometry/surface_binding.hpp"
#include "geometry/tube.hpp"
#include "geometry/vertex_normals.hpp"
#include "math/pose.hpp"
#include "precision.hpp"

namespace imasim::geometry {
namespace {

constexpr double kRadius = 0.00125;

std::vector<Vec3> arc(double bend) {  // 100 mm centerline, bent into an arc of angle `bend`
  std::vector<Vec3> c;
  for (int k = 0; k <= 40; ++k) {
    const double s = 0.1 * k / 40.0;
    if (bend == 0) {
      c.emplace_back(0, 0, s);
    } else {
      const double r = 0.1 / bend;
      c.emplace_back(r * (1 - std::cos(s / r)), 0, r * std::sin(s / r));
    }
  }
  return c;
}

struct Pair {
  TriangleMesh coarse, fine;
  std::vector<SurfaceBinding> bindings;
};

Pair make_pair() {
  Pair p;
  p.coarse = make_tube({arc(0), kRadius, 6, 20});
  p.fine = make_tube({arc(0), kRadius, 12, 40});
  p.bindings = bind_to_surface(p.fine.vertices, p.coarse, 4 * kRadius);
  return p;
}

std::vector<Vec3> rebuild(const Pair& p, const std::vector<Vec3>& coarse_positions) {
  std::vector<Vec3> normals(coarse_positions.size()), out(p.fine.vertex_count());
  compute_vertex_normals(coarse_positions, p.coarse.triangles, normals);
  apply_bindings(p.bindings, coarse_positions, normals, p.coarse.triangles, out);
  return out;
}

TEST(SurfaceBinding, FineMeshHasFourTimesTheVertices) {
  const Pair p = make_pair();
  EXPECT_EQ(p.fine.vertex_count(), 4 * p.coarse.vertex_count());
}

TEST(SurfaceBinding, ReproducesTheFineMeshAtRest) {
  const Pair p = make_pair();
  const std::vector<Vec3> fine = rebuild(p, p.coarse.vertices);
  for (std::size_t i = 0; i < fine.size(); ++i) {
    EXPECT_LT((fine[i] - p.fine.vertices[i]).norm(), test::ulps(16, 0.1));
  }
}

TEST(SurfaceBinding, RigidMotionMovesTheFineMeshRigidly) {
  const Pair p = make_pair();
  Pose pose;
  pose.rotation = axis_angle(Vec3(0.3, -1, 0.5), 0.7);
  pose.translation = Vec3(0.02, -0.05, 0.1);
  std::vector<Vec3> moved = p.coarse.vertices;
  for (Vec3& x : moved)
    x = pose.apply(x);
  const std::vector<Vec3> fine = rebuild(p, moved);
  for (std::size_t i = 0; i < fine.size(); ++i) {
    EXPECT_LT((fine[i] - pose.apply(p.fine.vertices[i])).norm(), test::ulps(32, 0.2));
  }
}

TEST(SurfaceBinding, UnderBendingFineVerticesStayNearTheCoarseSurface) {
  const Pair p = make_pair();
  // The rest offset of a fine vertex from the hexagonal coarse tube is at most r (1 - cos 30 deg).
  const double rest_offset = kRadius * (1 - std::cos(3.14159265358979 / 6));
  // Bend the coarse tube by 90 degrees over its 100 mm (same topology, new positions).
  const TriangleMesh bent = make_tube({arc(3.14159265358979 / 2), kRadius, 6, 20});
  const std::vector<Vec3> fine = rebuild(p, bent.vertices);
  double worst = 0;
  for (const Vec3& x : fine) {
    double best = 1e9;
    for (const Triangle& t : bent.triangles) {
      best = std::min(
          best, std::sqrt(closest_point_on_triangle(x, bent.vertices[t[0]], bent.vertices[t[1]],
                                                    bent.vertices[t[2]])
                              .distance2));
    }
    worst = std::max(worst, best);
  }
  // Stated tolerance: the rest offset plus 10 % of the radius.
  EXPECT_LT(worst, rest_offset + 0.1 * kRadius);
  EXPECT_GT(worst, 0.5 * rest_offset);  // the fine vertices do stand off the coarse facets
}

TEST(SurfaceBinding, RefusesPointsOutOfReach) {
  const Pair p = make_pair();
  const std::vector<Vec3> far = {Vec3(1, 1, 1)};
  EXPECT_THROW(bind_to_surface(far, p.coarse, 0.01), std::invalid_argument);
}

}  // namespace
}  // namespace imasim::geometry
