// Several offscreen contexts in one process: EGL hands every caller the same
// surfaceless display, so a context that goes must not end the others, and each draws into its
// own framebuffer whichever was made last.
#include <gtest/gtest.h>

#include <cstdint>
#include <optional>
#include <vector>

#include "render/camera.hpp"
#include "render/offscreen_context.hpp"
#include "render/renderer.hpp"

using namespace imasim::render;

namespace {

constexpr int kWidth = 64, kHeight = 48;

// A fat sphere 5 cm in front of the eye, in the key colours.
std::vector<std::uint8_t> draw_sphere(OffscreenContext& context, Renderer& renderer) {
  Camera camera;
  camera.projection = orbit_camera(OrbitCamera{}, float(kWidth) / kHeight).projection;
  for (int k = 0; k < 4; ++k)
    camera.view[std::size_t(5 * k)] = 1;  // the eye at the origin, looking along -z
  RenderFrame frame;
  frame.fat.centres = {0, 0, -0.05f};
  frame.fat.radii = {0.005f};
  context.bind();
  renderer.draw(frame, camera, {0, 0, kWidth, kHeight}, DrawMode::look_colours);
  return context.read_rgb();
}

int lit_pixels(const std::vector<std::uint8_t>& rgb) {
  int n = 0;
  for (std::size_t i = 0; i + 2 < rgb.size(); i += 3)
    n += rgb[i] != 0 || rgb[i + 1] != 0 || rgb[i + 2] != 0;
  return n;
}

}  // namespace

TEST(OffscreenContext, AContextKeepsDrawingAfterAnotherComesAndGoes) {
  OffscreenContext first(kWidth, kHeight);
  Renderer first_renderer;
  const std::vector<std::uint8_t> before = draw_sphere(first, first_renderer);
  ASSERT_GT(lit_pixels(before), 50);
  {
    std::optional<OffscreenContext> second(std::in_place, kWidth, kHeight);
    std::optional<Renderer> second_renderer(std::in_place);
    EXPECT_EQ(draw_sphere(*second, *second_renderer), before);
    // The first draws into its own framebuffer while the second is still alive.
    EXPECT_EQ(draw_sphere(first, first_renderer), before);
    second->bind();
    second_renderer.reset();
    second.reset();
  }
  EXPECT_EQ(draw_sphere(first, first_renderer), before);
}
