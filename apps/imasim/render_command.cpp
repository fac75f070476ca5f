#include "render_command.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <nlohmann/json.hpp>

#include "cli_checks.hpp"
#include "command_inputs.hpp"
#include "job_estimate.hpp"
#include "physics/executor.hpp"
#include "render/camera.hpp"
#include "render/frame_of_session.hpp"
#include "render/image_file.hpp"
#include "render/offscreen_context.hpp"
#include "render/renderer.hpp"
#include "render/stereo_view.hpp"
#include "runner/session_runner.hpp"
#include "scene/scene_file.hpp"
#include "session/surgical_session.hpp"
#include "surgery/input_script.hpp"

namespace imasim::cli {

std::shared_ptr<RenderOptions> add_render_command(CLI::App& app) {
  auto opt = std::make_shared<RenderOptions>();
  CLI::App* cmd = app.add_subcommand(
      "render", "Step the session headless and write frames drawn offscreen as PNG files");
  cmd->add_option("--scene", opt->scene_file, "Scene file (TOML); default: the built-in scene")
      ->check(CLI::ExistingFile);
  cmd->add_option("--script", opt->script_file, "Input script driving the instruments")
      ->check(CLI::ExistingFile);
  cmd->add_option("--patient-seed", opt->patient_seed, "Virtual patient (0: the scene's own)");
  cmd->add_flag("--static", opt->static_heart, "Hold the heart at its static phase");
  cmd->add_option("--frames", opt->frames, "Frames to write")
      ->required()
      ->check(CLI::Range(1, 100000));
  cmd->add_option("--out", opt->out_dir, "Directory for frame_0000.png ...")->required();
  cmd->add_option("--width", opt->width, "Image width (pixels)")->check(CLI::Range(16, 8192));
  cmd->add_option("--height", opt->height, "Image height (pixels)")->check(CLI::Range(16, 8192));
  cmd->add_option("--fps", opt->fps, "Frames per simulated second")
      ->check(finite_range(1.0, 200.0));
  cmd->add_option("--camera", opt->camera, "endoscope (the camera port's scope) or orbit")
      ->check(CLI::IsMember({"endoscope", "orbit"}));
  cmd->add_option("--stereo", opt->stereo, "none, side-by-side or anaglyph")
      ->check(CLI::IsMember({"none", "side-by-side", "anaglyph"}));
  cmd->add_flag("--key-colours", opt->key_colours,
                "Each tissue in its flat key colour, unlit (docs/rendering.md)");
  cmd->add_flag("--json", opt->json, "Print a JSON summary");
  cmd->add_flag("--yes", opt->yes, "Start even when the estimate is over an hour or 10 GB");
  return opt;
}

int run_render_command(const RenderOptions& o) {
  scene::ThoraxSceneParams params;
  std::optional<surgery::InputScript> script;
  if (!load_scene_params(o.scene_file, params) || !load_script(o.script_file, script)) return 2;
  if (o.static_heart) params.playback.beating = false;
  if (o.patient_seed) params.anatomy.patient_seed = *o.patient_seed;
  if (!confirm_job("imasim render",
                   std::to_string(o.frames) + " frames of " + std::to_string(o.width) + "x" +
                       std::to_string(o.height),
                   render_estimate(std::uint64_t(o.frames), std::uint64_t(o.width),
                                   std::uint64_t(o.height), o.fps),
                   o.yes, std::cerr))
    return 2;
  std::error_code ec;
  std::filesystem::create_directories(o.out_dir, ec);
  if (ec || !std::filesystem::is_directory(o.out_dir)) {
    std::cerr << "imasim render: cannot make the directory " << o.out_dir << ": " << ec.message()
              << '\n';
    return 4;
  }
  std::optional<session::SurgicalSession> session;
  try {
    session = session::make_surgical_session(params, session::SessionParams{});
  } catch (const std::exception& e) {
    std::cerr << "imasim render: cannot build the scene: " << e.what() << '\n';
    return 2;
  }
  std::optional<render::OffscreenContext> context;
  std::optional<render::Renderer> renderer;
  try {
    context.emplace(o.width, o.height);
    renderer.emplace();
  } catch (const std::exception& e) {
    std::cerr << "imasim render: " << e.what() << '\n';
    return 3;
  }

  physics::Executor exec(1);
  render::RenderFrame frame;
  render::frame_of_session(*session, frame);
  const render::OrbitCamera orbit = render::default_orbit(frame);
  const double dt = session->scene.patch.world.model.solver.dt;
  double draw_ms = 0;
  std::optional<runner::ScriptInput> script_input;
  runner::IdleInput idle;
  runner::InputSource& input =
      script ? static_cast<runner::InputSource&>(script_input.emplace(*script)) : idle;
  runner::SessionRunner run(*session, input, exec);
  for (int k = 0; k < o.frames; ++k) {
    // Step until the frame's simulated time.
    const double t_frame = double(k) / o.fps;
    while (double(run.steps_done()) * dt + 0.5 * dt < t_frame) {
      if (!run.step().ok()) {
        std::cerr << "imasim render: the step failed at " << double(run.steps_done()) * dt
                  << " s\n";
        return 1;
      }
    }
    const auto t0 = std::chrono::steady_clock::now();
    render::frame_of_session(*session, frame);
    context->bind();
    const float aspect = render::stereo_aspect(o.stereo, o.width, o.height);
    const render::Camera camera = o.camera == "orbit" ? render::orbit_camera(orbit, aspect)
                                                      : render::endoscope_camera(frame, aspect);
    if (o.key_colours)
      renderer->draw(frame, camera, {0, 0, o.width, o.height}, render::DrawMode::look_colours);
    else
      render::draw_view(*renderer, frame, camera, render::stereo_mode(o.stereo), o.width, o.height);
    render::RgbImage image{o.width, o.height, context->read_rgb()};
    draw_ms +=
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", k);
    const std::string path = (std::filesystem::path(o.out_dir) / name).string();
    try {
      render::write_png(path, image);
    } catch (const std::exception& e) {
      std::cerr << "imasim render: " << e.what() << '\n';
      return 4;
    }
  }
  if (o.json) {
    nlohmann::ordered_json j;
    j["frames"] = o.frames;
    j["width"] = o.width;
    j["height"] = o.height;
    j["simulated_s"] = double(run.steps_done()) * dt;
    j["draw_ms_per_frame"] = draw_ms / o.frames;
    j["renderer"] = context->renderer_name();
    j["out"] = o.out_dir;
    std::cout << j.dump(2) << '\n';
  } else {
    std::cout << "imasim render: " << o.frames << " frames in " << o.out_dir << " ("
              << context->renderer_name() << ")\n";
  }
  return 0;
}

}  // namespace imasim::cli
