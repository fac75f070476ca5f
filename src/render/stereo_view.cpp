#include "render/stereo_view.hpp"

#include <stdexcept>

namespace imasim::render {

StereoMode stereo_mode(const std::string& name) {
  if (name == "none") return StereoMode::none;
  if (name == "side-by-side") return StereoMode::side_by_side;
  if (name == "anaglyph") return StereoMode::anaglyph;
  throw std::invalid_argument("stereo mode must be none, side-by-side or anaglyph, not " + name);
}

float stereo_aspect(const std::string& name, int width, int height) {
  const float aspect = float(width) / float(height);
  return stereo_mode(name) == StereoMode::side_by_side ? aspect / 2 : aspect;
}

void draw_view(Renderer& renderer, const RenderFrame& frame, const Camera& camera, StereoMode mode,
               int width, int height, const StereoParams& stereo, int x, int y, Clear clear) {
  switch (mode) {
    case StereoMode::none:
      renderer.draw(frame, camera, {x, y, width, height}, DrawMode::lit, {true, true, true}, clear);
      return;
    case StereoMode::side_by_side: {
      const int half = width / 2;
      renderer.draw(frame, stereo_eye(camera, -1, stereo.separation, stereo.convergence),
                    {x, y, half, height}, DrawMode::lit, {true, true, true}, clear);
      renderer.draw(frame, stereo_eye(camera, +1, stereo.separation, stereo.convergence),
                    {x + half, y, width - half, height}, DrawMode::lit, {true, true, true}, clear);
      return;
    }
    case StereoMode::anaglyph:
      renderer.draw(frame, stereo_eye(camera, -1, stereo.separation, stereo.convergence),
                    {x, y, width, height}, DrawMode::lit, {true, false, false}, clear);
      // The right eye over the left: its clear and its drawing touch only green and blue.
      renderer.draw(frame, stereo_eye(camera, +1, stereo.separation, stereo.convergence),
                    {x, y, width, height}, DrawMode::lit, {false, true, true});
      return;
  }
}

}  // namespace imasim::render
