#pragma once
// `imasim window`: the interactive simulator. The session steps in real time on its
// own thread; the window draws its latest frame with the panels (instruments, forces, metrics,
// score card) and takes the keyboard and mouse as the console, with any live device of
// `imasim run --devices` beside them, or plays an input script. `imasim` with no arguments
// opens it where there is a display.
#include <CLI/CLI.hpp>
#include <iosfwd>
#include <memory>
#include <string>

namespace imasim::cli {

struct WindowCommandOptions {
  std::string scene_file;   // empty: the built-in scene
  std::string script_file;  // plays the instruments (the keyboard then only runs the window)
  std::string devices;      // "" (keyboard, or the script), keyboard, gamepad, ...
  bool pedal = false;
  bool static_heart = false;
  double seconds = 0;  // > 0: quit when the session reaches this simulated time
  std::string screenshot;
  int width = 1280, height = 720;
  double quit_key_after = -1;
  int threads = 1;
  double max_fps = 60;
  bool no_vsync = false;
  bool orbit = false;
  std::string stereo = "none";
  std::string record_file;
  bool json = false;
};

std::shared_ptr<WindowCommandOptions> add_window_command(CLI::App& app);

// Exit codes: 0 done; 2 bad input or no display (nothing run); 3 the session's last step was
// refused; 4 the screenshot could not be written; 5 OpenGL reported errors.
int run_window_command(const WindowCommandOptions& options);

// Where a window can open (X11's $DISPLAY or Wayland's $WAYLAND_DISPLAY is set).
bool display_available();
// What to run without a display.
void print_headless_hint(std::ostream& out);

}  // namespace imasim::cli
