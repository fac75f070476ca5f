#pragma once
// The headless input script (docs/input_script.md): a text file of time-stamped commands that
// drives the two instrument arms and the endoscope in `imasim run --headless --script FILE`.
// Parsing checks everything up front and throws InputScriptError ("PATH:LINE: message"), so a
// run never starts on a half-valid script; sampling is then a binary search per track, with no
// allocation, safe to call every step.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "math/pose.hpp"
#include "surgery/instrument.hpp"
#include "surgery/pedal.hpp"

namespace imasim::surgery {

// Which pose an instrument track gives: the console hand (through the arm's scaling and remote
// centre of motion) or the tool's hinge directly in the scene frame. One per track.
enum class PoseSource : std::uint8_t { none, hand, tool };

struct PoseKey {
  double time = 0;  // (unit: s)
  Pose pose;        // translation (unit: m)
};

template <class T>
struct Timed {
  double time = 0;  // (unit: s)
  T value{};
};

// Keys in file order, times non-decreasing.
struct InstrumentTrack {
  PoseSource source = PoseSource::none;  // none while `poses` is empty
  std::vector<PoseKey> poses;
  std::vector<Timed<JawCommand>> jaw;
  std::vector<Timed<bool>> clutch;  // true = engaged
  std::vector<Timed<PedalMode>> pedal;
  std::vector<Timed<Real>> power;  // (unit: W)
};

struct CameraTrack {
  std::vector<Timed<Real>> optics;     // optics angle, 0 or 30 degrees (unit: rad)
  std::vector<Timed<Real>> insertion;  // tip beyond the port (unit: m)
  std::vector<Timed<Real>> roll;       // about the shaft (unit: rad)
};

struct InputScript {
  std::string path;  // for messages only
  InstrumentTrack left, right;
  CameraTrack camera;

  // The time of the last command line (unit: s); 0 for a script without commands.
  double end_time() const;
};

class InputScriptError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Parses a whole script; `path` only prefixes the messages. Throws InputScriptError.
InputScript parse_input_script(std::string_view text, const std::string& path);

// Reads and parses the file at `path`. Throws InputScriptError, also when it cannot be read.
InputScript load_input_script(const std::string& path);

// The commands in force at one time.
struct InstrumentInput {
  PoseSource source = PoseSource::none;  // none: the script gives no pose, `pose` is identity
  Pose pose;                             // hand or tool pose, per `source` (unit: m)
  JawCommand jaw = JawCommand::hold;
  bool clutch = false;
  PedalMode pedal = PedalMode::off;
  Real power = 40;  // (unit: W)
  // The device driving this instrument (its hand, or the cautery's pedal) is gone: the session
  // holds the instrument still with no energy and records device_lost (console/loss_guard.hpp).
  bool device_lost = false;
};

struct CameraInput {
  Real optics = 0;                // (unit: rad)
  std::optional<Real> insertion;  // empty: not given, the scene's value stands (unit: m)
  std::optional<Real> roll;       // empty: not given (unit: rad)
};

// The values at time t (unit: s): poses interpolated (linear position, slerp rotation) and held
// outside the keys; each discrete command is the last one at or before t, else its default.
// Binary searches, no allocation. t must not be NaN.
InstrumentInput sample_instrument(const InstrumentTrack& track, double t);
CameraInput sample_camera(const CameraTrack& track, double t);

}  // namespace imasim::surgery
