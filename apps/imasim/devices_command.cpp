#include "devices_command.hpp"

#include <iostream>
#include <nlohmann/json.hpp>

#include "devices/emulated_console.hpp"
#include "devices/gamepad_device.hpp"
#include "devices/igtl_device.hpp"
#include "devices/spacemouse_device.hpp"
#include "report.hpp"

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
  cmd->add_flag("--json", opt->json, "Print one JSON object on stdout");
  return opt;
}

int run_devices_command(const DevicesOptions& o) {
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  {
    devices::IgtlDeviceConfig config;  // the protocol's port on loopback
    nlohmann::ordered_json j;
    try {
      const devices::IgtlDevice igtl(config);
      j = describe(igtl.info(),
                   "imasim run --devices openigtlink (trackers and devices call "
                   "127.0.0.1:18944)");
      j["listening_possible"] = true;
    } catch (const devices::IgtlLinkError& e) {
      devices::DeviceInfo d;
      d.kind = "openigtlink";
      d.name = "127.0.0.1:18944";
      j = describe(d, "imasim run --devices openigtlink --igtl-port P");
      j["listening_possible"] = false;
      j["problem"] = e.what();
    }
    list.push_back(j);
  }
  {
    nlohmann::ordered_json j;
    try {
      const devices::GamepadDevice pad;
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
    devices::SpaceMouseDevice mouse;
    devices::ConsoleInput probe;
    mouse.poll(0.0, probe);
    list.push_back(describe(mouse.info(), "imasim run --devices spacemouse"));
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
