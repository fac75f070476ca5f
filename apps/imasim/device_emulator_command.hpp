#pragma once
// `imasim device-emulator [--script FILE] [--address A] [--port P] [--seconds T] [--json]`: a
// separate program that behaves like two desktop haptic devices on an OpenIGTLink console
// (devices/emulated_console.hpp): each hand a mass-spring-damper at 1 kHz steered along the
// script's path for that hand (console hand or tool poses), applying the force imasim sends
// back; the script's jaw commands become a jaw value at the jaws' rate, its clutch, pedal and
// power are sent as they change; --loop plays it over and over. It calls imasim's OpenIGTLink
// server (`imasim run --devices openigtlink`, or spawned by `--devices emulator`), so the whole
// loop runs on one machine.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <memory>
#include <string>

namespace imasim::cli {

struct DeviceEmulatorOptions {
  std::string script_file;  // empty: the built-in example script (example_script.hpp)
  std::string scene_file;   // for the device names (devices.*); empty: the defaults
  std::string address = "127.0.0.1";
  std::uint16_t port = 18944;
  double seconds = 0;  // 0: the script's end + 0.5 s
  double wait_s = 10;  // for the server to answer
  bool loop = false;   // play the script again from its start after its end + 0.5 s
  bool json = false;
};

std::shared_ptr<DeviceEmulatorOptions> add_device_emulator_command(CLI::App& app);
int run_device_emulator_command(const DeviceEmulatorOptions& options);

}  // namespace imasim::cli
