#pragma once
// `imasim devices [--json]`: what can drive the simulator here and how each is mapped: the
// OpenIGTLink link (whether its port is free to listen on), the game controllers SDL2 sees, a 3D
// mouse (whether spacenavd answers), the device emulator and input scripts. With --listen: which
// OpenIGTLink device names arrive (devices_listen.hpp).
#include <CLI/CLI.hpp>
#include <memory>
#include <string>

namespace imasim::cli {

struct DevicesOptions {
  bool json = false;
  std::string scene_file;  // empty: the built-in scene's mappings
  bool listen = false;     // listen for OpenIGTLink peers instead of listing (devices_listen.hpp)
  double listen_seconds = 10;
  int igtl_port = -1;  // -1: the scene's
};

std::shared_ptr<DevicesOptions> add_devices_command(CLI::App& app);
int run_devices_command(const DevicesOptions& options);

}  // namespace imasim::cli
