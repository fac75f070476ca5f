// The heart's surface velocity (tissue/heart_field.hpp), which the haptic loop's local model
// uses to carry the heart's contact plane between physics steps: the time derivative of the
// playback now (not the last step's mean), at a vertex that vertex's, inside a triangle the
// barycentric mix. Checked against central differences of the playback itself.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "scene/thorax_scene.hpp"
#include "tissue/heart.hpp"
#include "tissue/heart_field.hpp"

namespace imasim::tissue {
namespace {

constexpr Real kDt = Real(0.005);  // the physics step (unit: s)

scene::ThoraxScene advanced_scene(bool beating, double t) {
  scene::ThoraxSceneParams p = scene::default_thorax_scene_params();
  p.playback.beating = beating;
  scene::ThoraxScene s = scene::make_thorax_scene(p);
  advance_heart(s.heart, s.patch.world, t);
  return s;
}

// The heart's vertex velocities at time t by a central difference of the playback (unit: m/s).
std::vector<Vec3> differenced_velocities(const HeartField& heart, double t) {
  constexpr double h = 1e-6;  // (unit: s)
  std::vector<Vec3> ahead, behind;
  interpolate_heart(heart.model, heart.playback.phase_at(t + h), ahead);
  interpolate_heart(heart.model, heart.playback.phase_at(t - h), behind);
  std::vector<Vec3> v(ahead.size());
  for (std::size_t i = 0; i < v.size(); ++i)
    v[i] = (ahead[i] - behind[i]) / Real(2 * h);
  return v;
}

TEST(HeartVertexRate, IsTheDerivativeOfThePlaybackAcrossKeyframes) {
  const HeartModel model = make_procedural_heart(HeartParams{});
  const Real n = Real(model.keyframes.size());
  std::vector<Vec3> ahead, behind;
  constexpr Real h = Real(1e-7);  // (unit: cycles)
  Real largest = 0;
  // Inside spans, and on both sides of a keyframe (the interpolation is C1 there).
  for (const Real t : {Real(0.03), Real(0.1), Real(0.37), Real(0.7), Real(0.95), Real(3) / n,
                       Real(3) / n - Real(1e-9), Real(5) / n + Real(1e-9)}) {
    SCOPED_TRACE(t);
    interpolate_heart(model, t + h, ahead);
    interpolate_heart(model, t - h, behind);
    for (std::uint32_t v = 0; v < ahead.size(); v += 37) {
      const Vec3 differenced = (ahead[v] - behind[v]) / (2 * h);
      const Vec3 rate = heart_vertex_rate(model, t, v);
      EXPECT_LT((rate - differenced).norm(), 1e-6 * (1 + differenced.norm())) << "vertex " << v;
      largest = std::max(largest, rate.norm());
    }
  }
  EXPECT_GT(largest, 0.01);  // the wall moves centimetres per cycle
}

TEST(HeartSurfaceVelocity, AtAVertexAndInsideATriangleDuringEjection) {
  constexpr double t = 0.1;  // early systole: the wall moves fast (unit: s)
  scene::ThoraxScene s = advanced_scene(true, t);
  HeartField& heart = s.heart;
  const std::vector<Vec3> vertex_velocity = differenced_velocities(heart, t);
  const auto& tris = heart.model.topology.triangles;
  Real fastest = 0;
  for (std::size_t k = 0; k < tris.size(); k += 97) {
    const auto& tri = tris[k];
    const Vec3 at_vertex = heart_surface_velocity(heart, heart.current[tri[0]], 0.01);
    EXPECT_LT((at_vertex - vertex_velocity[tri[0]]).norm(), 1e-6) << "triangle " << k;
    const Vec3 centroid =
        (heart.current[tri[0]] + heart.current[tri[1]] + heart.current[tri[2]]) / 3;
    const Vec3 expected =
        (vertex_velocity[tri[0]] + vertex_velocity[tri[1]] + vertex_velocity[tri[2]]) / 3;
    EXPECT_LT((heart_surface_velocity(heart, centroid, 0.01) - expected).norm(), 1e-6)
        << "triangle " << k;
    fastest = std::max(fastest, expected.norm());
  }
  EXPECT_GT(fastest, 0.005);  // a beating heart's wall moves several mm/s at least
}

// The velocity is the surface's now, not its mean over the last step. Carried one step dt with
// it, a point misses the playback's next position by dt^2 x'' / 2; carried with the last step's
// mean velocity, by dt^2 x'' (Taylor series): half the error, to leading order.
TEST(HeartSurfaceVelocity, CarriesThePlaneNearerToWhereTheWallWillBe) {
  constexpr double t = 0.1;  // (unit: s)
  scene::ThoraxScene s = advanced_scene(true, t);
  HeartField& heart = s.heart;
  std::vector<Vec3> before, after;
  interpolate_heart(heart.model, heart.playback.phase_at(t - kDt), before);
  interpolate_heart(heart.model, heart.playback.phase_at(t + kDt), after);
  Real error_now = 0, error_mean = 0;
  for (std::uint32_t v = 0; v < heart.current.size(); v += 11) {
    const Vec3 now = heart_surface_velocity(heart, heart.current[v], 0.01);
    const Vec3 mean = (heart.current[v] - before[v]) / kDt;
    error_now += (heart.current[v] + kDt * now - after[v]).norm();
    error_mean += (heart.current[v] + kDt * mean - after[v]).norm();
  }
  EXPECT_GT(error_mean, 0);
  EXPECT_LT(error_now, 0.6 * error_mean) << error_now << " " << error_mean;
}

TEST(HeartSurfaceVelocity, ZeroWhenStaticOrFarAway) {
  scene::ThoraxScene still = advanced_scene(false, 0.1);
  EXPECT_EQ(heart_surface_velocity(still.heart, still.heart.current[0], 0.01), Vec3::Zero());
  scene::ThoraxScene beating = advanced_scene(true, 0.1);
  EXPECT_EQ(heart_surface_velocity(beating.heart, Vec3(10, 10, 10), 0.01), Vec3::Zero());
}

}  // namespace
}  // namespace imasim::tissue
