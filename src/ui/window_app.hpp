#pragma once
// The interactive window: GLFW with an OpenGL 3.3 core context, the 3D view drawn by
// render::Renderer from the physics thread's latest frame (endoscope or orbit camera, mono or
// stereo), the Dear ImGui panels over it, and the keyboard and mouse as the console. Checks
// glGetError after every frame.
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>

#include "render/stereo_view.hpp"
#include "ui/keyboard_mouse_device.hpp"
#include "ui/sim_thread.hpp"

namespace imasim::ui {

struct WindowOptions {
  int width = 1280, height = 720;  // of the window's drawable area (unit: pixels)
  bool vsync = true;
  double max_fps = 60;              // frames drawn at most per second (0: no limit)
  bool quit_when_finished = false;  // quit once the session reached its end time
  std::string screenshot;           // "": none; else the last image as PNG, before quitting
  // Seconds of wall-clock time after which an Escape key press is made through the window's
  // key handler (tests); negative: never.
  double quit_key_after_s = -1;
  // Polled once a frame: true quits as the window's close button does (a signal's handler).
  std::function<bool()> should_quit;
  bool orbit = false;  // start with the orbit camera instead of the endoscope
  render::StereoMode stereo = render::StereoMode::none;
};

struct WindowReport {
  std::string quit;  // "key", "closed", "finished", "signal"
  std::uint64_t frames = 0;
  // From the time between consecutive frames, the first second left out (start-up).
  double median_fps = 0, p99_frame_ms = 0, mean_fps = 0;
  std::uint64_t gl_errors = 0;
  std::string gl_renderer;  // "llvmpipe (LLVM 15.0.6, 256 bits)"
  bool screenshot_written = false;
  std::string screenshot_error;  // why it was not
};

class WindowError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Call before any thread starts (setenv is not thread-safe). Mesa's software rasteriser,
// llvmpipe, starts one rasterising thread per core; beside them the physics thread keeps part of
// a core busy, and the thread that shares its core finishes its tiles last while the frame waits.
// One thread more than the cores spreads the tiles so that the others take up the slack
// (docs/PERFORMANCE.md). Leaves a LP_NUM_THREADS the user set alone; a GPU's driver ignores it.
void spread_software_rasteriser_threads();

// Opens the window, starts `sim` and runs until the window is closed, Escape is pressed or (with
// quit_when_finished) the session ends; stops `sim`. `keyboard` (may be null) receives the
// console's keys and the mouse drags. Throws WindowError, before starting `sim`, when no window
// or no OpenGL 3.3 context can be had (no display, say) or the renderer cannot start.
WindowReport run_window(const WindowOptions& options, SimThread& sim,
                        KeyboardMouseDevice* keyboard);

}  // namespace imasim::ui
