#include "metrics/trajectory_recorder.hpp"

#include <cmath>
#include <cstdio>

namespace imasim::metrics {

namespace {

// 9 significant digits: a nanometre at a metre, a microsecond at 1000 s.
void add_number(std::string& line, double v) {
  char text[32];
  std::snprintf(text, sizeof text, ",%.9g", std::isfinite(v) ? v : 0.0);
  line += text;
}

}  // namespace

std::vector<TrajectoryColumn> trajectory_columns() {
  std::vector<TrajectoryColumn> c = {{"t_s", "s", "simulated time of the sample"}};
  for (const std::string_view tool_view : kToolNames) {
    const std::string tool(tool_view);
    const std::string what = tool == "forceps" ? "the forceps' tip (midpoint of the jaw tips)"
                                               : "the hook's tip (end of the electrode)";
    for (const char* axis : {"x", "y", "z"})
      c.push_back({tool + "_" + axis, "m", std::string(axis) + " of " + what + ", scene frame"});
    for (const char* q : {"qw", "qx", "qy", "qz"})
      c.push_back({tool + "_" + q, "1", std::string(q) + " of the instrument's orientation"});
    c.push_back({tool + "_jaw_rad", "rad", "jaw opening angle (eq. 16)"});
    for (const char* axis : {"x", "y", "z"})
      c.push_back({tool + "_device_" + axis, "m",
                   std::string(axis) + " of the pose the hand or script asked for (the proxy's "
                                       "target before tissue stops it)"});
    c.push_back({tool + "_clutch", "1", "1 while the clutch is held"});
    c.push_back({tool + "_force_normal_n", "N", "normal force on the hand (eq. 17)"});
    c.push_back({tool + "_force_tangential_n", "N", "tangential force on the hand (eq. 18)"});
    c.push_back({tool + "_force_thermal_n", "N", "thermal force on the hand (eq. 19)"});
    c.push_back({tool + "_contact", "",
                 "tissue pressed the most: none, fascia, ima, fat, heart, "
                 "chest_wall"});
  }
  c.push_back({"pedal", "", "cautery pedal: off, cut, coag"});
  c.push_back({"power_w", "W", "electrosurgical power while the pedal is pressed"});
  return c;
}

std::string trajectory_csv_header() {
  std::string h;
  for (const TrajectoryColumn& c : trajectory_columns())
    h += (h.empty() ? "" : ",") + c.name;
  return h + '\n';
}

std::string trajectory_csv_line(const TrajectorySample& s) {
  char time[32];
  std::snprintf(time, sizeof time, "%.9g", s.time);
  std::string line = time;
  for (const ToolSample& t : s.tools) {
    for (int k = 0; k < 3; ++k)
      add_number(line, double(t.tip[k]));
    for (const Real q : t.orientation)
      add_number(line, double(q));
    add_number(line, double(t.jaw_angle));
    for (int k = 0; k < 3; ++k)
      add_number(line, double(t.device[k]));
    line += t.clutch ? ",1" : ",0";
    add_number(line, double(t.force_normal));
    add_number(line, double(t.force_tangential));
    add_number(line, double(t.force_thermal));
    line += ',';
    line += surgery::to_string(t.contact);
  }
  line += ',';
  line += surgery::to_string(s.pedal);
  add_number(line, double(s.power_w));
  return line + '\n';
}

TrajectoryRecorder::TrajectoryRecorder(OutputFile file) : file_(std::move(file)) {
  file_.write(trajectory_csv_header());
  file_.flush();
}

bool TrajectoryRecorder::due(double time) const {
  // A step lands on a sample time within rounding (1/60 s is no multiple of 5 ms).
  return time >= next_ - 1e-9;
}

void TrajectoryRecorder::record(const TrajectorySample& sample) {
  file_.write(trajectory_csv_line(sample));
  ++rows_;
  // The next multiple of 1/60 s after this sample.
  next_ = (std::floor(sample.time * kRecordRateHz + 1e-6) + 1) / kRecordRateHz;
  file_.flush_if_due();
}

void TrajectoryRecorder::finish() {
  file_.close();
}

nlohmann::ordered_json trajectory_side_file(const nlohmann::ordered_json& run) {
  nlohmann::ordered_json j;
  j["format"] = "imasim trajectory v1";
  j["rate_hz"] = kRecordRateHz;
  j["sampling"] =
      "one row at the first physics step that reaches each multiple of 1/60 s (rows 15 or 20 ms "
      "apart with 5 ms steps); t_s is the step's time";
  j["units"] = "SI: m, s, rad, N, W";
  j["run"] = run;
  nlohmann::ordered_json columns = nlohmann::ordered_json::array();
  for (const TrajectoryColumn& c : trajectory_columns())
    columns.push_back({{"name", c.name}, {"unit", c.unit}, {"meaning", c.meaning}});
  j["columns"] = columns;
  return j;
}

}  // namespace imasim::metrics
