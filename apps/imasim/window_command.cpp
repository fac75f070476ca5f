#include "window_command.hpp"
#include "command_inputs.hpp"

#include <signal.h>
#include <sys/wait.h>

#include <cstdlib>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>

#include "cli_checks.hpp"
#include "console/console_settings_use.hpp"
#include "interrupt.hpp"
#include "live_inputs.hpp"
#include "report.hpp"
#include "runner/input_source.hpp"
#include "scene/scene_file.hpp"
#include "ui/key_bindings.hpp"
#include "ui/window_app.hpp"

namespace imasim::cli {

namespace {

// The emulator child of `--devices emulator`, ended with the window.
class EmulatorProcess {
 public:
  explicit EmulatorProcess(pid_t pid) : pid_(pid) {}
  ~EmulatorProcess() {
    if (pid_ <= 0) return;
    ::kill(pid_, SIGTERM);
    int status = 0;
    ::waitpid(pid_, &status, 0);
  }
  EmulatorProcess(const EmulatorProcess&) = delete;
  EmulatorProcess& operator=(const EmulatorProcess&) = delete;

 private:
  pid_t pid_;
};

nlohmann::ordered_json score_json(const ui::ScoreCard& c) {
  nlohmann::ordered_json j;
  j["heart"] = c.beating ? "dynamic" : "static";
  j["duration_s"] = c.duration_s;
  j["strands_cut"] = c.strands_cut;
  j["strands_total"] = c.strands_total;
  j["strands_torn"] = c.strands_torn;
  j["fascia_edges_cut"] = c.fascia_edges_cut;
  j["ima_injuries"] = c.ima_injuries;
  j["instrument_collisions"] = c.instrument_collisions;
  j["heart_touches"] = c.heart_touches;
  j["chest_wall_touches"] = c.wall_touches;
  if (c.sai_available) j["sai"] = {{"forceps", c.sai[0]}, {"hook", c.sai[1]}};
  j["metrics_passed"] = c.passed;
  j["metrics_total"] = c.metrics.size();
  return j;
}

}  // namespace

bool display_available() {
  const char* x = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x && *x) || (wayland && *wayland);
}

void print_headless_hint(std::ostream& out) {
  out << "imasim: no display ($DISPLAY is not set), so no window. Without one:\n"
         "  imasim run --headless --script examples/open_fascia.script   (a scripted session)\n"
         "  imasim render --script examples/open_fascia.script --frames 10 --out frames/\n"
         "  xvfb-run -a imasim window --seconds 10 --screenshot shot.png   (a virtual display)\n"
         "  imasim --help   (every subcommand)\n";
}

std::shared_ptr<WindowCommandOptions> add_window_command(CLI::App& app) {
  auto opt = std::make_shared<WindowCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "window",
      "The interactive simulator: a window with the endoscope's view, the panels and "
      "keyboard and mouse control (F1 lists the keys)");
  cmd->add_option("--scene", opt->scene_file, "Scene file (TOML); default: the built-in scene")
      ->check(non_empty());
  cmd->add_option("--script", opt->script_file,
                  "Input script playing the instruments (docs/input_script.md)")
      ->check(non_empty());
  cmd->add_option("--devices", opt->devices,
                  "Input: keyboard (with the mouse; the default without --script), gamepad, "
                  "spacemouse, openigtlink or emulator (--script played on emulated haptic "
                  "devices); the keys drive what the device does not")
      ->check(CLI::IsMember({"keyboard", "gamepad", "spacemouse", "openigtlink", "emulator",
                             "openhaptics", "force_dimension"}));
  cmd->add_flag("--pedal", opt->pedal, "Foot pedals from a joystick's buttons beside --devices");
  cmd->add_flag("--static", opt->static_heart,
                "Start with the heart frozen at its static phase (the panel switches it)");
  cmd->add_option("--seconds", opt->seconds,
                  "Quit when the session reaches this simulated time (s); 0: run until closed")
      ->check(finite_range(0.0, 3600.0));
  cmd->add_option("--screenshot", opt->screenshot,
                  "Save the window's last image here (PNG) before quitting")
      ->check(non_empty());
  cmd->add_option("--width", opt->width, "Window width (pixels)")
      ->capture_default_str()
      ->check(CLI::Range(320, 7680));
  cmd->add_option("--height", opt->height, "Window height (pixels)")
      ->capture_default_str()
      ->check(CLI::Range(240, 4320));
  cmd->add_option("--quit-key-after", opt->quit_key_after,
                  "Press Escape through the window's key handler after this many seconds of "
                  "wall-clock time (tests)")
      ->check(finite_range(0.0, 86400.0));
  cmd->add_option("--threads", opt->threads, "Physics worker threads (0 = all cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, 1024));
  cmd->add_option("--max-fps", opt->max_fps, "Frames drawn at most per second (0: no limit)")
      ->capture_default_str()
      ->check(finite_range(0.0, 1000.0));
  cmd->add_flag("--no-vsync", opt->no_vsync, "Do not wait for the display's refresh");
  cmd->add_flag("--orbit", opt->orbit, "Start with the orbit camera instead of the endoscope");
  cmd->add_option("--stereo", opt->stereo, "Stereo: none, side-by-side or anaglyph")
      ->capture_default_str()
      ->check(CLI::IsMember({"none", "side-by-side", "anaglyph"}));
  cmd->add_option("--record", opt->record_file,
                  "Where the Record button writes the 60 Hz trajectory (CSV, a JSON side file "
                  "beside it); default: imasim-window.csv")
      ->check(non_empty());
  cmd->add_flag("--json", opt->json, "Print the summary as one JSON object");
  return opt;
}

int run_window_command(const WindowCommandOptions& o) {
  if (!display_available()) {
    std::cerr << "imasim window: cannot open a window: no display ($DISPLAY is not set)\n";
    print_headless_hint(std::cerr);
    return 2;
  }
  ui::spread_software_rasteriser_threads();  // first: no thread of ours runs yet
  ui::SimConfig config;
  std::optional<surgery::InputScript> script;
  if (!load_scene_params(o.scene_file, config.scene) || !load_script(o.script_file, script))
    return 2;
  if (!o.scene_file.empty()) config.scene_name = o.scene_file;
  if (o.static_heart) config.scene.playback.beating = false;
  const std::string devices = !o.devices.empty() ? o.devices : script ? "script" : "keyboard";
  if (devices == "emulator" && !script) {
    std::cerr << "imasim window: --devices emulator needs --script (the path to play)\n";
    return 2;
  }
  if (script && devices != "script" && devices != "emulator") {
    std::cerr << "imasim window: --devices " << devices
              << " takes its input from the devices, not --script\n";
    return 2;
  }
  if (o.pedal && (devices == "script" || devices == "keyboard")) {
    std::cerr << "imasim window: --pedal goes with --devices gamepad, spacemouse, openigtlink or "
                 "emulator\n";
    return 2;
  }
  config.threads = o.threads;
  config.end_s = o.seconds > 0 ? o.seconds : script ? script->end_time() + 0.5 : 0;
  config.record_path = o.record_file;

  // The input: the script, or the console with the keyboard first and any live device after it
  // (polled later, so a device's hands and pedal win where both drive them).
  std::unique_ptr<runner::InputSource> input;
  ui::KeyboardMouseDevice* keyboard = nullptr;
  std::optional<EmulatorProcess> emulator;
  try {
    if (devices == "script") {
      input = std::make_unique<runner::ScriptInput>(*script);
    } else {
      std::vector<std::unique_ptr<devices::InputDevice>> list;
      auto kb =
          std::make_unique<ui::KeyboardMouseDevice>(ui::KeyboardMapping{}, ui::bindings_text());
      keyboard = kb.get();
      list.push_back(std::move(kb));
      std::uint16_t port = 0;
      if (devices != "keyboard") {
        LiveInputOptions lo;
        lo.devices = devices;
        lo.script_file = o.script_file;
        lo.scene_file = o.scene_file;
        lo.settings = config.scene.console;
        lo.pedal = o.pedal;
        if (devices == "emulator") lo.port = 0;  // any free port, told to the child
        bool left = true, right = true, pedal = true;
        for (auto& d : make_live_devices(lo, port)) {
          const devices::DeviceInfo info = d->info();
          left = left && !info.drives_left;
          right = right && !info.drives_right;
          pedal = pedal && !info.drives_pedal;
          list.push_back(std::move(d));
        }
        // The keys drive only what no device does (each device writes what it owns).
        keyboard->set_drives(left, right, pedal);
      }
      console::LiveConsoleParams params = console::live_console_params(config.scene.console);
      // The keyboard alone renders no force: the loop only reads keys, so it sleeps to each
      // tick instead of spinning the last part (a core's tenth back for drawing and physics).
      if (devices == "keyboard") params.loop.spin_s = 0;
      input = std::make_unique<runner::ConsoleInputSource>(std::move(list), params,
                                                           [keyboard] { keyboard->reset(); });
      if (devices == "emulator") {
        const double plays = o.seconds > 0 ? o.seconds + 1 : 24 * 3600.0;
        emulator.emplace(spawn_emulator(o.script_file, o.scene_file, port, plays, false));
      }
    }
  } catch (const std::exception& e) {
    std::cerr << "imasim window: " << e.what() << '\n';
    return 2;
  }

  std::unique_ptr<ui::SimThread> sim;
  try {
    sim = std::make_unique<ui::SimThread>(config, std::move(input));
  } catch (const std::exception& e) {
    std::cerr << "imasim window: cannot build the scene: " << e.what() << '\n';
    return 2;
  }
  ui::WindowOptions w;
  w.width = o.width;
  w.height = o.height;
  w.vsync = !o.no_vsync;
  w.max_fps = o.max_fps;
  w.quit_when_finished = o.seconds > 0;
  w.screenshot = o.screenshot;
  w.quit_key_after_s = o.quit_key_after;
  w.orbit = o.orbit;
  w.stereo = render::stereo_mode(o.stereo);
  install_interrupt_handlers();
  w.should_quit = [] { return interrupt_signal() != 0; };
  ui::WindowReport report;
  try {
    report = ui::run_window(w, *sim, keyboard);
  } catch (const ui::WindowError& e) {
    std::cerr << "imasim window: " << e.what() << '\n';
    if (!display_available()) print_headless_hint(std::cerr);
    return 2;
  }
  ui::LiveNumbers last;
  sim->latest_numbers(last);
  const std::optional<ui::ScoreCard> card = sim->score_card();
  const std::optional<console::LiveConsoleStats> loop = sim->console_stats();
  sim.reset();  // the physics thread and the console's loop are stopped; the emulator next
  emulator.reset();

  nlohmann::ordered_json out;
  out["scene"] = config.scene_name;
  out["input"] = devices;
  out["quit"] = report.quit;
  out["state"] = ui::to_string(last.state);
  out["simulated_s"] = last.time_s;
  out["frames"] = report.frames;
  out["median_fps"] = report.median_fps;
  out["mean_fps"] = report.mean_fps;
  out["p99_frame_ms"] = report.p99_frame_ms;
  // Over the whole session: simulated time over the wall-clock time it ran (pauses left out).
  out["realtime_factor"] = last.running_s > 0 ? last.time_s / last.running_s : 0.0;
  out["gl_renderer"] = report.gl_renderer;
  out["gl_errors"] = report.gl_errors;
  out["width"] = o.width;
  out["height"] = o.height;
  if (!o.screenshot.empty()) out["screenshot"] = report.screenshot_written ? o.screenshot : "";
  if (loop) {
    const haptics::HapticLoopStats& l = loop->loop;
    out["haptic_loop"] = {{"ticks", l.ticks},
                          {"rate_hz", l.rate_hz},
                          {"period_p99_error_us", l.period_p99_error_us},
                          {"period_max_us", l.period_max_us},
                          {"missed_deadlines", l.missed_deadlines},
                          {"latency_p99_us", l.latency_p99_us},
                          {"realtime_priority", l.realtime},
                          {"force_max_n", loop->force_max_n}};
    out["devices_lost"] = loss_report(*loop);
    out["devices_refused"] = loop->refused;
  }
  if (card) out["score"] = score_json(*card);
  if (!print_report(out, o.json)) {
    std::cerr << "imasim window: cannot write the report to stdout\n";
    return 4;
  }
  if (!o.screenshot.empty() && !report.screenshot_written) {
    std::cerr << "imasim window: " << report.screenshot_error << '\n';
    return 4;
  }
  if (report.gl_errors > 0) {
    std::cerr << "imasim window: OpenGL reported " << report.gl_errors << " error(s)\n";
    return 5;
  }
  if (const int signal = interrupt_signal(); signal != 0) return interrupted_exit_status(signal);
  return last.state == ui::SimState::failed ? 3 : 0;
}

}  // namespace imasim::cli
