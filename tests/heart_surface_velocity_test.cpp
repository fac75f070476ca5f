// The heart's surface velocity (tissue/heart_field.hpp), which the haptic loop's local model
// uses to carry the heart's contact plane between physics steps: at a vertex it is that vertex's
// displacement over the last advance divided by dt; inside a triangle, the barycentric mix.
#include <gtest/gtest.h>

#include "scene/thorax_scene.hpp"
#include "tissue/heart_field.hpp"

namespace imasim::tissue {
namespace {

constexpr Real kDt = Real(0.005);  // (unit: s)

struct AdvancedHeart {
  scene::ThoraxScene scene;
  explicit AdvancedHeart(bool beating, double t) : scene(make(beating)) {
    advance_heart(scene.heart, scene.patch.world, t);
    advance_heart(scene.heart, scene.patch.world, t + kDt);
  }
  static scene::ThoraxScene make(bool beating) {
    scene::ThoraxSceneParams p = scene::default_thorax_scene_params();
    p.playback.beating = beating;
    return scene::make_thorax_scene(p);
  }
  Vec3 vertex_velocity(std::uint32_t v) const {
    return (scene.heart.current[v] - scene.heart.previous[v]) / kDt;
  }
};

TEST(HeartSurfaceVelocity, AtAVertexAndInsideATriangleDuringEjection) {
  AdvancedHeart h(true, 0.1);  // early systole: the wall moves fast
  HeartField& heart = h.scene.heart;
  const auto& tris = heart.model.topology.triangles;
  Real fastest = 0;
  for (std::size_t t = 0; t < tris.size(); t += 97) {
    const auto& tri = tris[t];
    const Vec3 at_vertex = heart_surface_velocity(heart, heart.current[tri[0]], 0.01, kDt);
    EXPECT_LT((at_vertex - h.vertex_velocity(tri[0])).norm(), 1e-9) << "triangle " << t;
    const Vec3 centroid =
        (heart.current[tri[0]] + heart.current[tri[1]] + heart.current[tri[2]]) / 3;
    const Vec3 expected =
        (h.vertex_velocity(tri[0]) + h.vertex_velocity(tri[1]) + h.vertex_velocity(tri[2])) / 3;
    EXPECT_LT((heart_surface_velocity(heart, centroid, 0.01, kDt) - expected).norm(), 1e-9)
        << "triangle " << t;
    fastest = std::max(fastest, expected.norm());
  }
  EXPECT_GT(fastest, 0.005);  // a beating heart's wall moves several mm/s at least
}

TEST(HeartSurfaceVelocity, ZeroWhenStaticFarAwayOrWithoutATimeStep) {
  AdvancedHeart still(false, 0.1);
  HeartField& heart = still.scene.heart;
  const Vec3 on_surface = heart.current[0];
  EXPECT_EQ(heart_surface_velocity(heart, on_surface, 0.01, kDt), Vec3::Zero());
  AdvancedHeart beating(true, 0.1);
  EXPECT_EQ(heart_surface_velocity(beating.scene.heart, Vec3(10, 10, 10), 0.01, kDt), Vec3::Zero());
  EXPECT_EQ(heart_surface_velocity(beating.scene.heart, beating.scene.heart.current[0], 0.01, 0),
            Vec3::Zero());
}

}  // namespace
}  // namespace imasim::tissue
