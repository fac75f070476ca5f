#include "device_emulator_command.hpp"

#include <chrono>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <thread>

#include "cli_checks.hpp"
#include "console/console_settings_use.hpp"
#include "devices/emulated_console.hpp"
#include "example_script.hpp"
#include "interrupt.hpp"
#include "report.hpp"
#include "scene/scene_file.hpp"
#include "surgery/input_script.hpp"

namespace imasim::cli {

namespace {

// The jaw value (0 open .. 1 closed) moves at the jaws' button rate over their range (eq. 16's
// theta_dot / theta_max, default 120 / 30 degrees: a full stroke in 0.25 s).
Real jaw_rate() {
  const surgery::JawParams jaws;
  return jaws.button_rate / jaws.max_angle;
}

}  // namespace

std::shared_ptr<DeviceEmulatorOptions> add_device_emulator_command(CLI::App& app) {
  auto opt = std::make_shared<DeviceEmulatorOptions>();
  CLI::App* cmd = app.add_subcommand("device-emulator",
                                     "Two emulated haptic devices driving imasim over OpenIGTLink");
  cmd->add_option("--script", opt->script_file,
                  "Input script giving each hand's path (default: the built-in "
                  "examples/open_fascia.script)")
      ->check(non_empty());
  cmd->add_option("--scene", opt->scene_file, "Scene file naming the devices (devices.*)")
      ->check(non_empty());
  cmd->add_option("--address", opt->address, "imasim's OpenIGTLink server")->capture_default_str();
  cmd->add_option("--port", opt->port, "Its port")
      ->capture_default_str()
      ->check(CLI::Range(1, 65535));
  cmd->add_option("--seconds", opt->seconds, "How long to play (0: the script's end + 0.5 s)")
      ->check(finite_range(0, 3600));
  cmd->add_option("--wait", opt->wait_s, "Seconds to wait for the server")
      ->capture_default_str()
      ->check(finite_range(0, 600));
  cmd->add_flag("--loop", opt->loop, "Play the script over and over (each cycle its end + 0.5 s)");
  cmd->add_flag("--json", opt->json, "Print one JSON object on stdout at the end");
  return opt;
}

int run_device_emulator_command(const DeviceEmulatorOptions& o) {
  surgery::InputScript script;
  try {
    script = load_script_or_example(o.script_file);
  } catch (const surgery::InputScriptError& e) {
    std::cerr << e.what() << '\n';
    return 2;
  }
  devices::IgtlNames names;
  if (!o.scene_file.empty()) {
    try {
      names = console::igtl_device_config(scene::load_scene_file(o.scene_file).console).link.names;
    } catch (const scene::SceneFileError& e) {
      for (const std::string& m : e.messages())
        std::cerr << m << '\n';
      return 2;
    }
  }
  const double cycle = script.end_time() + 0.5;
  const double seconds = o.seconds > 0 ? o.seconds : cycle;
  std::unique_ptr<devices::EmulatedConsole> console;
  try {
    console = std::make_unique<devices::EmulatedConsole>(o.address, o.port, o.wait_s,
                                                         devices::EmulatedHandParams{}, names);
  } catch (const std::exception& e) {
    std::cerr << "imasim device-emulator: " << e.what() << '\n';
    return 2;
  }
  install_interrupt_handlers();
  using Clock = std::chrono::steady_clock;
  const Clock::time_point start = Clock::now();
  devices::EmulatorTarget target;
  target.jaw = {1, 1};  // the instruments start closed
  Real force_max = 0;
  std::uint64_t ticks = 0;
  bool lost = false;
  for (; interrupt_signal() == 0; ++ticks) {
    const double t = double(ticks) * 1e-3;
    if (t > seconds) break;
    std::this_thread::sleep_until(start + std::chrono::microseconds(ticks * 1000));
    const surgery::InstrumentTrack* tracks[2] = {&script.left, &script.right};
    for (int h = 0; h < 2; ++h) {
      const surgery::InstrumentInput in =
          surgery::sample_instrument(*tracks[h], o.loop ? std::fmod(t, cycle) : t);
      target.has_pose[h] = in.source != surgery::PoseSource::none;
      target.pose[h] = in.pose;
      target.frame[h] = in.source == surgery::PoseSource::tool ? devices::PoseFrame::tool
                                                               : devices::PoseFrame::hand;
      target.clutch[h] = in.clutch;
      const Real step = Real(1e-3) * jaw_rate();
      if (in.jaw == surgery::JawCommand::close)
        target.jaw[h] = std::min(Real(1), target.jaw[h] + step);
      if (in.jaw == surgery::JawCommand::open)
        target.jaw[h] = std::max(Real(0), target.jaw[h] - step);
      if (h == 1) {
        target.pedal = in.pedal == surgery::PedalMode::cut    ? haptics::CauteryMode::cut
                       : in.pedal == surgery::PedalMode::coag ? haptics::CauteryMode::coag
                                                              : haptics::CauteryMode::off;
        target.power_w = in.power;
      }
    }
    // Time stamps from the device's own clock, as a device sends them.
    const double stamp = std::chrono::duration<double>(Clock::now() - start).count() + 1.0;
    if (!console->tick(stamp, target)) {
      lost = true;
      break;
    }
    for (const Vec3& f : console->force())
      force_max = std::max(force_max, f.norm());
  }
  nlohmann::ordered_json out;
  out["ticks"] = ticks;
  out["seconds"] = double(ticks) * 1e-3;
  out["forces_received"] = console->forces_received();
  out["force_max_n"] = force_max;
  out["status"] = lost ? "connection_lost" : interrupt_signal() != 0 ? "interrupted" : "ok";
  if (!print_report(out, o.json)) return 4;
  if (const int signal = interrupt_signal(); signal != 0) return interrupted_exit_status(signal);
  return 0;
}

}  // namespace imasim::cli
