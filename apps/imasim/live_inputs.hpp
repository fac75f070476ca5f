#pragma once
// Where `imasim run` takes each step's input from (`--devices`):
//   script       the input script, sampled at the step's simulated time (headless, as fast as
//                the machine steps);
//   replay       a recorded input stream (console/input_stream.hpp), one line a step;
//   openigtlink  live devices over OpenIGTLink (imasim the server, or a client of a tracker's
//                server), stepped in real time with the 1 kHz haptic loop rendering forces;
//   emulator     the same, with `imasim device-emulator` started as a child process playing
//                the script on two emulated haptic devices over loopback;
//   gamepad      a game controller through SDL2 (both hands and the pedal), real time;
//   spacemouse   a 3D mouse through spacenavd (the right hand), real time;
// any of the live ones with foot pedals from a joystick's buttons beside them (`--pedal`).
#include <sys/types.h>
#include <array>
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "console/live_console.hpp"
#include "runner/input_source.hpp"
#include "scene/console_settings.hpp"
#include "session/surgical_session.hpp"
#include "surgery/input_script.hpp"

namespace imasim::cli {

struct LiveInputOptions {
  std::string devices;      // "openigtlink", "emulator", "gamepad" or "spacemouse"
  std::string script_file;  // the emulator's script
  std::string scene_file;   // the emulator reads the device names from it too
  scene::ConsoleSettings settings = scene::default_console_settings();  // the scene file's
  std::optional<std::string> address;  // overrides the settings' OpenIGTLink address
  std::optional<std::uint16_t> port;   // overrides its port; 0: any free (the emulator is told)
  bool client = false;                 // call a tracker's server instead of listening
  bool pedal = false;                  // add foot pedals from a joystick (settings' mapping)
  // The emulator plays this long; 0: until finish() stops it (a run that falls behind real time
  // must not see its own emulator leave as a lost device).
  double seconds = 0;
  bool loop_script = false;  // the emulator plays the script over and over
  bool realtime_priority = true;
  std::string program = "imasim run";  // names the program in its stderr lines
};

// The devices a live input starts (the hands' device, then the pedals with `pedal`), for
// LiveInputs and for the window (which adds the keyboard); `port` receives the OpenIGTLink
// link's port (for the emulator), unchanged without a link. Throws std::runtime_error with a
// message for the user.
std::vector<std::unique_ptr<devices::InputDevice>> make_live_devices(const LiveInputOptions& o,
                                                                     std::uint16_t& port);

// Per console part (left, right, pedal): how often its device was lost, for how long, and
// whether it was still held at the end.
nlohmann::ordered_json loss_report(const console::LiveConsoleStats& stats);

// Starts `imasim device-emulator` (this very program) playing `script` to `port`; its summary
// goes to /dev/null. Throws std::runtime_error when it cannot start.
pid_t spawn_emulator(const std::string& script, const std::string& scene, std::uint16_t port,
                     double seconds, bool loop);

// A runner input source: run it with real-time pacing (runner/session_runner.hpp).
class LiveInputs final : public runner::InputSource {
 public:
  // Starts the link (and the emulator); throws std::runtime_error with a message for the user.
  explicit LiveInputs(const LiveInputOptions& options);
  ~LiveInputs() override;
  LiveInputs(const LiveInputs&) = delete;
  LiveInputs& operator=(const LiveInputs&) = delete;

  session::SessionInput next(const session::SurgicalSession& session) override;
  // After a step: publishes the local models; says a refusal or a loss on stderr as it happens.
  void after_step(const session::SurgicalSession& session, std::uint64_t steps_done) override;
  void stop() override { finish(); }
  // Stops the loop and the emulator; the report's "devices" object.
  nlohmann::ordered_json finish();

 private:
  console::LiveConsole* console_ = nullptr;
  std::unique_ptr<console::LiveConsole> owned_;
  pid_t emulator_ = -1;
  bool finished_ = false;
  std::array<bool, 2> told_lost_{};  // per instrument: a loss said on stderr, not yet its end
  std::uint32_t told_refusals_ = 0;  // refusal reasons said on stderr
  std::string program_;
  nlohmann::ordered_json report_;
};

}  // namespace imasim::cli
