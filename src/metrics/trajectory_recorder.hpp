#pragma once
// The session recorder (SPEC S6): per instrument the tip's position and orientation,
// the jaw angle, the device (hand) position and clutch, the force per channel (eq. 17-19:
// normal, tangential, thermal) and the tissue in contact; the pedal and its power; sampled at
// 60 Hz (the paper's rate) and written as the run goes: whole lines, flushed at least once a
// second, so a killed run leaves a file that loads up to its last flush. Plain CSV that pandas
// reads with no options (a header, commas, '.' decimals, no quoting, no index column); a JSON
// side file says what the columns mean and in which units, and what was run.
#include <array>
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "math/types.hpp"
#include "metrics/output_file.hpp"
#include "surgery/events.hpp"
#include "surgery/pedal.hpp"

namespace imasim::metrics {

inline constexpr double kRecordRateHz = 60;  // the paper's sampling rate (3)

struct ToolSample {
  Vec3 tip = Vec3::Zero();                      // (unit: m)
  std::array<Real, 4> orientation{1, 0, 0, 0};  // unit quaternion w, x, y, z of the instrument
  Real jaw_angle = 0;                           // (unit: rad)
  Vec3 device = Vec3::Zero();                   // the pose asked for, before the proxy (unit: m)
  bool clutch = false;
  Real force_normal = 0, force_tangential = 0, force_thermal = 0;  // eq. 17-19 (unit: N)
  surgery::Tissue contact = surgery::Tissue::none;                 // pressed the most
};

struct TrajectorySample {
  double time = 0;                  // simulated (unit: s)
  std::array<ToolSample, 2> tools;  // forceps, hook
  surgery::PedalMode pedal = surgery::PedalMode::off;
  Real power_w = 0;  // while the pedal is pressed (unit: W)
};

// The instruments' names in the columns: "forceps", "hook".
inline constexpr std::array<std::string_view, 2> kToolNames = {"forceps", "hook"};

// One column: its name, unit and meaning (the side file lists them all, in order).
struct TrajectoryColumn {
  std::string name, unit, meaning;
};
std::vector<TrajectoryColumn> trajectory_columns();

std::string trajectory_csv_header();  // with its newline
std::string trajectory_csv_line(const TrajectorySample& sample);

class TrajectoryRecorder {
 public:
  // Writes the header at once (flushed: even an empty run leaves a valid file).
  explicit TrajectoryRecorder(OutputFile file);

  // Whether a sample is due at simulated time `time`: the first at 0, then one at each step
  // that reaches the next multiple of 1/60 s (so rows are 15 or 20 ms apart with 5 ms steps).
  bool due(double time) const;
  // Appends the row, flushing when a second has passed; throws OutputError.
  void record(const TrajectorySample& sample);
  // Flushes and closes, checking that everything reached the file.
  void finish();

  std::size_t rows() const { return rows_; }
  const std::string& path() const { return file_.path(); }

 private:
  OutputFile file_;
  std::size_t rows_ = 0;
  double next_ = 0;  // simulated time of the next sample (unit: s)
};

// The side file's body: the columns' names, units and meanings, the rate, and `run` (what was
// run: scene, seed, heart mode, version, ... as the caller gives them).
nlohmann::ordered_json trajectory_side_file(const nlohmann::ordered_json& run);

}  // namespace imasim::metrics
