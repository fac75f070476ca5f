#pragma once
// `imasim devices --listen [--seconds S] [--igtl-port P] [--json]`: listens as `run --devices
// openigtlink` would and shows which OpenIGTLink device names and types arrive, and what each
// becomes (a hand's pose, its buttons, the pedal, or refused as a name the scene does not map),
// so that a user can map a tracker's "Tracker" or "StylusToReference" to a hand.
#include <cstdint>
#include <optional>

#include "scene/console_settings.hpp"

namespace imasim::cli {

struct ListenOptions {
  double seconds = 10;                // how long to listen (Ctrl-C ends it sooner)
  std::optional<std::uint16_t> port;  // default: the scene's devices.igtl_port
  bool json = false;
};

// 0 after listening, 2 when the port cannot be listened on, 4 when the report cannot be written.
int listen_for_devices(const scene::ConsoleSettings& settings, const ListenOptions& options);

}  // namespace imasim::cli
