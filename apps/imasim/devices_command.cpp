#include "devices_command.hpp"

#include <iostream>
#include <nlohmann/json.hpp>

#include "cli_checks.hpp"
#include "console/console_settings_use.hpp"
#include "devices/emulated_console.hpp"
#include "devices/gamepad_device.hpp"
#include "devices/igtl_device.hpp"
#include "devices/joystick_pedal_device.hpp"
#include "devices/spacemouse_device.hpp"
#include "devices_listen.hpp"
#include "report.hpp"
#include "scene/scene_file.hpp"

namespace imasim::cli {

namespace {

nlohmann::ordered_json describe(const devices::DeviceInfo& d, const std::string& use) {
  nlohmann::ordered_json j;
  j["kind"] = d.kind;
  j["name"] = d.name;
  j["connected"] = d.connected;
  j["force_feedback"] = d.force_feedback;
  if (d.max_force_n > 0) j["max_force_n"] = d.max_force_n;
  j["drives"] = std::string(d.drives_left ? "left " : "") + (d.drives_right ? "right " : "") +
                (d.drives_pedal ? "pedal" : "");
  j["mapping"] = d.mapping;
  j["use"] = use;
  return j;
}

}  // namespace

std::shared_ptr<DevicesOptions> add_devices_command(CLI::App& app) {
  auto opt = std::make_shared<DevicesOptions>();
  CLI::App* cmd = app.add_subcommand("devices", "List the input devices and how they are mapped");
  cmd->add_option("--scene", opt->scene_file,
                  "Scene file whose devices.* keys map the devices; default: the built-in scene")
      ->check(non_empty());
  cmd->add_flag("--json", opt->json, "Print one JSON object on stdout");
  CLI::Option* listen =
      cmd->add_flag("--listen", opt->listen,
                    "Listen for OpenIGTLink peers and show which device names and types arrive and "
                    "what each becomes under the scene's mapping");
  // Refused without --listen, whatever the value (the default's too): CLI11 says which it needs.
  cmd->add_option("--seconds", opt->listen_seconds, "With --listen: how long to listen")
      ->check(CLI::Range(0.01, 86400.0))
      ->needs(listen);
  cmd->add_option("--igtl-port", opt->igtl_port,
                  "With --listen: the port (0: any free); default: the scene's devices.igtl_port")
      ->check(CLI::Range(0, 65535))
      ->needs(listen);
  return opt;
}

int run_devices_command(const DevicesOptions& o) {
  scene::ConsoleSettings settings = scene::default_console_settings();
  if (!o.scene_file.empty()) {
    try {
      settings = scene::load_scene_file(o.scene_file).console;
    } catch (const scene::SceneFileError& e) {
      for (const std::string& m : e.messages())
        std::cerr << m << '\n';
      return 2;
    }
  }
  if (o.listen) {
    ListenOptions listen;
    listen.seconds = o.listen_seconds;
    if (o.igtl_port >= 0) listen.port = std::uint16_t(o.igtl_port);
    listen.json = o.json;
    return listen_for_devices(settings, listen);
  }
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  {
    const devices::IgtlDeviceConfig config = console::igtl_device_config(settings);
    const std::string where = config.link.address + ":" + std::to_string(config.link.port);
    nlohmann::ordered_json j;
    try {
      const devices::IgtlDevice igtl(config);
      j = describe(igtl.info(),
                   "imasim run --devices openigtlink (trackers and devices call " + where + ")");
      j["listening_possible"] = true;
    } catch (const devices::IgtlLinkError& e) {
      devices::DeviceInfo d;
      d.kind = "openigtlink";
      d.name = where;
      j = describe(d, "imasim run --devices openigtlink --igtl-port P");
      j["listening_possible"] = false;
      j["problem"] = e.what();
    }
    list.push_back(j);
  }
  {
    nlohmann::ordered_json j;
    try {
      const devices::GamepadDevice pad(console::gamepad_mapping(settings));
      j = describe(pad.info(), "imasim run --devices gamepad");
    } catch (const std::exception& e) {
      devices::DeviceInfo d;
      d.kind = "gamepad";
      d.name = e.what();
      j = describe(d, "imasim run --devices gamepad");
    }
    j["controllers"] = devices::GamepadDevice::list_controllers();
    list.push_back(j);
  }
  {
    devices::SpaceMouseDevice mouse(console::spacemouse_mapping(settings));
    devices::ConsoleInput probe;
    mouse.poll(0.0, probe);
    list.push_back(describe(mouse.info(), "imasim run --devices spacemouse"));
  }
  {
    nlohmann::ordered_json j;
    try {
      const devices::JoystickPedalDevice pedal(console::pedal_mapping(settings));
      j = describe(pedal.info(), "imasim run --devices ... --pedal");
    } catch (const std::exception& e) {
      devices::DeviceInfo d;
      d.kind = "pedal";
      d.name = e.what();
      j = describe(d, "imasim run --devices ... --pedal");
    }
    list.push_back(j);
  }
  {
    devices::DeviceInfo d;
    d.kind = "emulator";
    d.name = "imasim device-emulator";
    d.connected = true;
    d.force_feedback = true;
    d.max_force_n = devices::EmulatedHandParams{}.max_force_n;
    d.drives_left = d.drives_right = d.drives_pedal = true;
    d.mapping = "two emulated desktop haptic devices over OpenIGTLink, playing an input script";
    list.push_back(describe(d, "imasim run --devices emulator --script FILE"));
  }
  {
    devices::DeviceInfo d;
    d.kind = "script";
    d.name = "input scripts and recorded streams";
    d.connected = true;
    d.drives_left = d.drives_right = d.drives_pedal = true;
    d.mapping = "docs/input_script.md; a recorded run: --record-input FILE, then --replay FILE";
    list.push_back(describe(d, "imasim run --headless --script FILE | --replay FILE"));
  }
  if (o.json) {
    nlohmann::ordered_json out;
    out["devices"] = list;
    return print_report(out, true) ? 0 : 4;
  }
  for (const auto& j : list) {
    std::cout << j["kind"].get<std::string>() << ": " << j["name"].get<std::string>()
              << (j["connected"].get<bool>() ? "" : " (not connected)")
              << "\n  use: " << j["use"].get<std::string>() << '\n';
    std::string mapping = j["mapping"].get<std::string>();
    for (std::size_t at = 0; !mapping.empty();) {
      const std::size_t end = mapping.find('\n', at);
      std::cout << "  " << mapping.substr(at, end - at) << '\n';
      if (end == std::string::npos) break;
      at = end + 1;
    }
    if (j.contains("controllers"))
      for (const auto& c : j["controllers"])
        std::cout << "  found: " << c.get<std::string>() << '\n';
  }
  return 0;
}

}  // namespace imasim::cli
