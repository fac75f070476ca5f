#pragma once
// `imasim render [--scene FILE] [--script FILE] [--static] [--patient-seed N] --frames K --out DIR
// [--width W --height H] [--fps F] [--camera endoscope|orbit] [--stereo none|side-by-side|
// anaglyph] [--key-colours] [--json]`: the session stepped headless (the script drives the
// instruments) and a frame drawn offscreen every 1/F s of simulated time (EGL, no display or GPU
// needed), written as DIR/frame_0000.png ... Bad input: exit 2; an unwritable frame: exit 4; no
// OpenGL: exit 3.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

namespace imasim::cli {

struct RenderOptions {
  std::string scene_file, script_file, out_dir;
  std::optional<std::uint64_t> patient_seed;
  bool static_heart = false;
  int frames = 1;
  int width = 1280, height = 720;
  double fps = 60;
  std::string camera = "endoscope";
  std::string stereo = "none";
  bool key_colours = false;  // each look in its flat key colour, unlit
  bool json = false;
  bool yes = false;  // start even when the estimate is over an hour or 10 GB
};

std::shared_ptr<RenderOptions> add_render_command(CLI::App& app);
int run_render_command(const RenderOptions& options);

}  // namespace imasim::cli
