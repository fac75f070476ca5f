// The cautery's glow: a warm point light at the electrode's tip while the pedal is
// pressed, drawn by its own compiled variant of the lighting (render/shader_variant.hpp). A
// square of chest wall and a fat sphere face the eye; the glow sits just in front of them.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <stdexcept>
#include <utility>
#include <vector>

#include "render/camera.hpp"
#include "render/offscreen_context.hpp"
#include "render/renderer.hpp"

using namespace imasim::render;

namespace {

constexpr int kWidth = 320, kHeight = 180;
constexpr float kWallDepth = 0.05f;  // the square's distance from the eye (unit: m)

struct Scene {
  OffscreenContext context{kWidth, kHeight};
  Renderer renderer;
  Camera camera;
  RenderFrame frame;

  Scene() {
    camera.projection = orbit_camera(OrbitCamera{}, float(kWidth) / kHeight).projection;
    for (int k = 0; k < 4; ++k)
      camera.view[std::size_t(5 * k)] = 1;  // the eye at the origin, looking along -z
    // A 60 mm square of chest wall facing the eye, a fat sphere in front of it, and the glow
    // between them, all off the view's axis: the scope's light at the eye puts its highlight
    // on the axis, where the wall is already at full red.
    Surface wall;
    wall.look = Look::chest_wall;
    const float h = 0.03f;
    wall.positions = {-h, -h, -kWallDepth, h,  -h, -kWallDepth,
                      h,  h,  -kWallDepth, -h, h,  -kWallDepth};
    wall.normals = {0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0, 1};
    wall.shade = {0, 0, 0, 0};
    wall.indices = {0, 1, 2, 0, 2, 3};
    frame.surfaces.push_back(wall);
    frame.fat.centres = {-0.012f, 0, -(kWallDepth - 0.002f)};
    frame.fat.radii = {0.0015f};
    frame.glow_position = {-0.018f, 0, -(kWallDepth - 0.003f)};  // 3 mm in front of the wall
  }

  std::vector<std::uint8_t> draw(bool glow, float strength) {
    frame.glow = glow;
    frame.glow_strength = strength;
    context.bind();
    renderer.draw(frame, camera, {0, 0, kWidth, kHeight});
    return context.read_rgb();
  }

  // The pixel (row from the top, as read_rgb gives them) where a camera-space point projects.
  static std::array<int, 2> pixel_of(const Camera& c, float x, float y, float z) {
    const float ndc_x = c.projection[0] * x / -z, ndc_y = c.projection[5] * y / -z;
    return {int((ndc_x + 1) / 2 * kWidth), int((1 - ndc_y) / 2 * kHeight)};
  }
};

std::array<int, 3> rgb_at(const std::vector<std::uint8_t>& rgb, std::array<int, 2> p) {
  if (p[0] < 0 || p[0] >= kWidth || p[1] < 0 || p[1] >= kHeight)
    throw std::out_of_range("the point projects outside the image");
  const std::size_t i = (std::size_t(p[1]) * kWidth + std::size_t(p[0])) * 3;
  return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

}  // namespace

TEST(OffscreenRender, TheCauteryGlowWarmsTheTissueNearTheElectrodeOnly) {
  Scene s;
  const std::vector<std::uint8_t> off = s.draw(false, 0);
  const std::vector<std::uint8_t> on = s.draw(true, 1);
  const auto under = Scene::pixel_of(s.camera, -0.018f, 0, -kWallDepth);
  // The sphere's side that faces the glow (its normal 0.6 towards it, out of its highlight).
  const auto sphere =
      Scene::pixel_of(s.camera, -0.012f - 0.6f * 0.0015f, 0, -(kWallDepth - 0.002f));
  const auto far = Scene::pixel_of(s.camera, 0.025f, 0, -kWallDepth);
  for (const auto& [name, p] :
       {std::pair{"wall under the tip", under}, std::pair{"fat sphere beside the tip", sphere}}) {
    const auto a = rgb_at(off, p), b = rgb_at(on, p);
    // The glow's colour is (1, 0.55, 0.15): red rises most, and far more than blue.
    EXPECT_GE(b[0] - a[0], 40) << name;
    EXPECT_GE(b[0] - a[0], 2 * (b[2] - a[2])) << name;
    EXPECT_GE(b[1] - a[1], 0) << name;
  }
  // 43 mm from the tip the light has fallen to 1.3 % of its strength there (shaders.hpp:
  // 1 / (1 + d^2 / 25 mm^2)), and meets the wall at a grazing angle: a few levels at most.
  const auto a = rgb_at(off, far), b = rgb_at(on, far);
  EXPECT_LE(b[0] - a[0], 6);
  EXPECT_GE(b[0] - a[0], 0);
}

// The glow switched off (the pedal up) with a strength left over, and switched on with none:
// both draw the picture without it.
TEST(OffscreenRender, NoGlowIsDrawnWithThePedalUpOrNoPower) {
  Scene s;
  EXPECT_EQ(s.draw(true, 0), s.draw(false, 1));
}
