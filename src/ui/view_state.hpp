#pragma once
// What the window shows and how (the drawing thread's own state): which camera, the orbit
// camera's pose, the stereo mode, which panels are open.
#include "render/camera.hpp"
#include "render/stereo_view.hpp"

namespace imasim::ui {

struct ViewState {
  bool orbit = false;  // false: the endoscope's view
  render::OrbitCamera orbit_camera;
  bool orbit_placed = false;  // set from the first frame's bounds
  render::StereoMode stereo = render::StereoMode::none;
  bool show_panels = true;
  bool show_help = false;
  bool show_score = false;
};

// The next stereo mode in the cycle off -> side by side -> anaglyph -> off.
inline render::StereoMode next_stereo(render::StereoMode m) {
  switch (m) {
    case render::StereoMode::none:
      return render::StereoMode::side_by_side;
    case render::StereoMode::side_by_side:
      return render::StereoMode::anaglyph;
    case render::StereoMode::anaglyph:
      break;
  }
  return render::StereoMode::none;
}

inline const char* stereo_name(render::StereoMode m) {
  switch (m) {
    case render::StereoMode::none:
      return "off";
    case render::StereoMode::side_by_side:
      return "side by side";
    case render::StereoMode::anaglyph:
      return "anaglyph (red-cyan)";
  }
  return "?";
}

}  // namespace imasim::ui
