#pragma once
// A view drawn once (mono) or as a stereo pair: side by side (each eye in half the width, for
// 3D displays and headsets) or anaglyph (left eye red, right eye cyan, in one image).
#include <string>

#include "render/camera.hpp"
#include "render/renderer.hpp"

namespace imasim::render {

enum class StereoMode { none, side_by_side, anaglyph };

struct StereoParams {
  float separation = 0.004f;  // between the eyes: a stereo endoscope's lenses (unit: m)
  float convergence = 0.06f;  // where the images coincide: the working distance (unit: m)
};

// "none", "side-by-side", "anaglyph"; throws std::invalid_argument for anything else.
StereoMode stereo_mode(const std::string& name);
// The aspect one eye's image has (half the width side by side).
float stereo_aspect(const std::string& name, int width, int height);

// Draws `camera`'s view into the rectangle of the bound framebuffer at x, y of size
// width x height. Clear::done_by_caller: the caller has cleared the rectangle (renderer.hpp).
void draw_view(Renderer& renderer, const RenderFrame& frame, const Camera& camera, StereoMode mode,
               int width, int height, const StereoParams& stereo = {}, int x = 0, int y = 0,
               Clear clear = Clear::viewport);

}  // namespace imasim::render
