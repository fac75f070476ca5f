// A fat sphere's point sprite (render/sphere_sprite.hpp): the square holds the sphere's whole
// outline, projected point by point from its silhouette circle, and is no larger than the
// outline's longer side plus the rounding margin; a sphere wholly out of view, or reaching the
// eye's plane, is no sprite; one across the edge keeps its sprite's centre inside the view.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "render/camera.hpp"
#include "render/sphere_order.hpp"
#include "render/sphere_sprite.hpp"

namespace imasim::render {
namespace {

constexpr float kWidth = 920, kHeight = 720;

// The eye at the origin looking along -z, the orbit camera's lens, a stereo eye's shifted
// frustum when `shift` is not zero.
Camera camera_at_origin(float shift = 0) {
  Camera c = orbit_camera(OrbitCamera{}, kWidth / kHeight);
  c.view = {};
  for (std::size_t k = 0; k < 4; ++k)
    c.view[5 * k] = 1;
  c.eye = {0, 0, 0};
  c.projection[8] = shift;
  return c;
}

// The outline's extreme pixel offsets from the sprite's centre: max |dx|, max |dy|, from 720
// points of the silhouette circle (the tangent points of the cone from the eye).
std::array<float, 2> outline_reach(const Camera& camera, const std::array<float, 3>& c, float r,
                                   const SpriteBounds& b) {
  const double L2 = double(c[0]) * c[0] + double(c[1]) * c[1] + double(c[2]) * c[2];
  const double L = std::sqrt(L2);
  const double k = 1 - double(r) * r / L2, rho = r * std::sqrt(L2 - double(r) * r) / L;
  // Two unit vectors across the view direction.
  std::array<double, 3> u{-c[1], double(c[0]), 0};
  double un = std::hypot(u[0], u[1]);
  if (un < 1e-12) u = {1, 0, 0}, un = 1;
  for (double& x : u)
    x /= un;
  const std::array<double, 3> n{c[0] / L, c[1] / L, c[2] / L};
  const std::array<double, 3> v{n[1] * u[2] - n[2] * u[1], n[2] * u[0] - n[0] * u[2],
                                n[0] * u[1] - n[1] * u[0]};
  const Matrix4& p = camera.projection;
  std::array<float, 2> reach{0, 0};
  for (int i = 0; i < 720; ++i) {
    const double a = 2 * M_PI * i / 720;
    std::array<double, 3> q{};
    for (std::size_t j = 0; j < 3; ++j)
      q[j] = k * c[j] + rho * (std::cos(a) * u[j] + std::sin(a) * v[j]);
    const double w = -q[2];
    const double ndc_x = (p[0] * q[0] + p[8] * q[2]) / w, ndc_y = (p[5] * q[1] + p[9] * q[2]) / w;
    reach[0] = std::max(reach[0], float(std::abs(ndc_x - b.centre_ndc[0]) * kWidth / 2));
    reach[1] = std::max(reach[1], float(std::abs(ndc_y - b.centre_ndc[1]) * kHeight / 2));
  }
  return reach;
}

TEST(SphereSprite, TheSquareHoldsTheWholeOutlineAndLittleMore) {
  std::mt19937 random(3);
  std::uniform_real_distribution<float> across(-0.6f, 0.6f), depth(0.004f, 0.2f),
      radius(0.0002f, 0.002f);
  int sprites = 0;
  for (float shift : {0.0f, 0.05f}) {
    const Camera camera = camera_at_origin(shift);
    for (int i = 0; i < 2000; ++i) {
      const float d = depth(random);
      const std::array<float, 3> c{across(random) * d, across(random) * d * 0.8f, -d};
      const float r = std::min(radius(random), 0.8f * d);
      const SpriteBounds b = sphere_sprite(camera, c, r, kWidth, kHeight);
      if (b.kind != SpriteBounds::Kind::sprite) continue;
      ++sprites;
      const std::array<float, 2> reach = outline_reach(camera, c, r, b);
      const float half = b.size_px / 2;
      EXPECT_LE(std::max(reach[0], reach[1]), half + 1e-3f * half) << "sphere " << i;
      // Not clamped at an edge: the square is the outline's longer side, 1 % and a pixel more.
      if (std::abs(b.centre_ndc[0]) < 0.99f && std::abs(b.centre_ndc[1]) < 0.99f) {
        EXPECT_GE(std::max(reach[0], reach[1]), (half - 0.5f) / 1.01f - 1e-3f * half);
      }
    }
  }
  EXPECT_GT(sprites, 3000);
}

TEST(SphereSprite, OutOfViewAtTheEyeAndAcrossTheEdge) {
  const Camera camera = camera_at_origin();
  const float half_width = 1 / camera.projection[0];
  // Wholly beyond the right edge, behind the eye, reaching the eye's plane.
  EXPECT_EQ(
      sphere_sprite(camera, {0.05f * half_width + 0.01f, 0, -0.05f}, 0.001f, kWidth, kHeight).kind,
      SpriteBounds::Kind::outside);
  EXPECT_EQ(sphere_sprite(camera, {0, 0, 0.05f}, 0.001f, kWidth, kHeight).kind,
            SpriteBounds::Kind::at_eye);
  EXPECT_EQ(sphere_sprite(camera, {0.0005f, 0, -0.0009f}, 0.001f, kWidth, kHeight).kind,
            SpriteBounds::Kind::at_eye);
  // Its centre just beyond the right edge, a part in view: the sprite's centre is inside and it
  // reaches the outline's far side.
  const std::array<float, 3> c{0.05f * (half_width + 0.01f), 0, -0.05f};
  const SpriteBounds b = sphere_sprite(camera, c, 0.002f, kWidth, kHeight);
  ASSERT_EQ(b.kind, SpriteBounds::Kind::sprite);
  EXPECT_LT(b.centre_ndc[0], 1.0f);
  const std::array<float, 2> reach = outline_reach(camera, c, 0.002f, b);
  EXPECT_LE(reach[0], b.size_px / 2);
}

TEST(SphereOrder, SplitSpritesDropsWhatIsOutOfViewAndSendsTooBigOnesToRectangles) {
  const Camera camera = camera_at_origin();
  Spheres fat;
  const auto add = [&](std::array<float, 3> c, float r) {
    for (float x : c)
      fat.centres.push_back(x);
    fat.radii.push_back(r);
  };
  add({0, 0, -0.05f}, 0.001f);      // 0: a sprite
  add({0, 0, -0.004f}, 0.0015f);    // 1: nearer, too big for a 255-pixel sprite
  add({0.5f, 0, -0.05f}, 0.001f);   // 2: out of view
  add({0.01f, 0, -0.08f}, 0.001f);  // 3: a sprite, farther
  add({0, 0, -0.0012f}, 0.0015f);   // 4: reaches the eye's plane
  SphereOrder order;
  order.sort(fat, camera.eye);
  order.split_sprites(camera, kWidth, kHeight, 230);
  ASSERT_EQ(order.radii().size(), 2u);
  EXPECT_EQ(order.centres()[2], -0.05f);  // nearest first
  EXPECT_EQ(order.centres()[5], -0.08f);
  ASSERT_EQ(order.near_radii().size(), 2u);
  EXPECT_EQ(order.near_centres()[2], -0.0012f);
  EXPECT_EQ(order.near_centres()[5], -0.004f);
  EXPECT_EQ(order.near_centres().size(), 6u);
}

}  // namespace
}  // namespace imasim::render
