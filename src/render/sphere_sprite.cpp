#include "render/sphere_sprite.hpp"

#include <algorithm>
#include <cmath>

namespace imasim::render {

namespace {

// The slopes (lateral / depth) of the two tangents to a circle of radius r about (x, d).
std::array<float, 2> tangent_slopes(float x, float d, float r) {
  const float t = std::sqrt(std::max(x * x + d * d - r * r, 0.0f));
  return {(x * t - d * r) / (d * t + x * r), (x * t + d * r) / (d * t - x * r)};
}

}  // namespace

SpriteBounds sphere_sprite(const Camera& camera, const std::array<float, 3>& centre, float radius,
                           float width, float height) {
  const Matrix4& v = camera.view;
  const Matrix4& p = camera.projection;
  std::array<float, 3> c{};
  for (int k = 0; k < 3; ++k)
    c[std::size_t(k)] = v[std::size_t(k)] * centre[0] + v[std::size_t(4 + k)] * centre[1] +
                        v[std::size_t(8 + k)] * centre[2] + v[std::size_t(12 + k)];
  const float d = -c[2];
  SpriteBounds b;
  if (d <= radius * 1.0001f) {
    b.kind = SpriteBounds::Kind::at_eye;
    return b;
  }
  const std::array<float, 2> sx = tangent_slopes(c[0], d, radius);
  const std::array<float, 2> sy = tangent_slopes(c[1], d, radius);
  // ndc = P00 slope - P20 (x), P11 slope - P21 (y): the frustum may be shifted (stereo).
  const std::array<float, 2> lo{p[0] * sx[0] - p[8], p[5] * sy[0] - p[9]};
  const std::array<float, 2> hi{p[0] * sx[1] - p[8], p[5] * sy[1] - p[9]};
  if (hi[0] < -1 || hi[1] < -1 || lo[0] > 1 || lo[1] > 1) return b;
  b.kind = SpriteBounds::Kind::sprite;
  const std::array<float, 2> pixels{width, height};
  float reach_px = 0;
  for (std::size_t k = 0; k < 2; ++k) {
    b.centre_ndc[k] = std::clamp(0.5f * (lo[k] + hi[k]), -0.999f, 0.999f);
    // Twice the half-extent in ndc, times half the viewport: the side in pixels.
    reach_px =
        std::max(reach_px, std::max(b.centre_ndc[k] - lo[k], hi[k] - b.centre_ndc[k]) * pixels[k]);
  }
  // 1 % and a pixel beyond the exact outline, for the rasteriser's rounding.
  b.size_px = 1.01f * reach_px + 1;
  return b;
}

}  // namespace imasim::render
