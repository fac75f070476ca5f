#include "surgery/input_script.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <initializer_list>
#include <iterator>
#include <limits>
#include <numbers>
#include <utility>

#include "math/angles.hpp"
#include "math/printable.hpp"
#include "math/text_file.hpp"

namespace imasim::surgery {

namespace {

// Limits of the file format (docs/input_script.md).
constexpr double kMaxCoordinate = 10;             // |x|, |y|, |z| of a pose (unit: m)
constexpr double kMinPower = 30, kMaxPower = 50;  // (unit: W)
constexpr double kMinInsertion = 0.01;            // (unit: m)
constexpr double kMaxInsertion = 0.3;             // (unit: m)
constexpr std::size_t kShownBytes = 40;           // a bad token is cut here in messages
constexpr std::size_t kMaxTokens = 9;             // time target hand x y z rx ry rz
constexpr double kTwoPi = 2 * std::numbers::pi;   // (unit: rad)
// The latest time a line may give: an hour, the longest `imasim run --seconds` accepts. A
// larger time is most often milliseconds written for seconds ("5000" for 5 s), which would
// silently make the run last that many seconds.
constexpr double kMaxTime = 3600;  // (unit: s)
// The largest script read: a 30-minute session with a pose every 5 ms step is about 22 MB.
constexpr std::uint64_t kMaxScriptBytes = std::uint64_t(64) << 20;

// A token as shown in a message: escaped and cut short (a line may be megabytes long).
std::string shown(std::string_view token) {
  return printable(token, kShownBytes);
}

// Built by appending: GCC 12 warns falsely (-Wrestrict) on "'" + std::string.
std::string quoted(std::string_view token) {
  std::string out = "'";
  out += shown(token);
  out += '\'';
  return out;
}

std::string shown_path(const std::string& path) {
  std::string out;
  append_printable(out, path, false);
  return out;
}

enum class NumberStatus : std::uint8_t { ok, bad, out_of_range };

// A finite decimal number and nothing else: std::from_chars is locale-independent and
// correctly rounded, so the same text gives the same bits everywhere. A leading '+' is allowed
// (from_chars alone refuses it); nan and inf are refused.
NumberStatus parse_number(std::string_view s, double& value) {
  if (s.size() > 1 && s.front() == '+' && s[1] != '-' && s[1] != '+') s.remove_prefix(1);
  const char* const end = s.data() + s.size();
  const auto [ptr, ec] = std::from_chars(s.data(), end, value, std::chars_format::general);
  if (ec == std::errc::result_out_of_range && ptr == end) return NumberStatus::out_of_range;
  if (ec != std::errc() || ptr != end) return NumberStatus::bad;
  return std::isfinite(value) ? NumberStatus::ok : NumberStatus::bad;
}

// A limit as the docs write it: the shortest text that reads back the same (30, 0.01).
std::string limit_text(double v) {
  std::array<char, 32> buffer{};
  const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), v);
  return std::string(buffer.data(), result.ptr);
}

std::string interval_text(double lo, double hi) {
  std::string out = "[";
  out += limit_text(lo);
  out += ", ";
  out += limit_text(hi);
  out += ']';
  return out;
}

// Whether the scene's scalar holds v (a float build cannot hold 1e300).
bool fits_real(double v) {
  return std::abs(v) <= double(std::numeric_limits<Real>::max());
}

class Parser {
 public:
  explicit Parser(const std::string& path) { script_.path = path; }

  void parse(std::string_view text) {
    std::size_t start = 0;
    while (start < text.size()) {
      std::size_t end = text.find('\n', start);
      if (end == std::string_view::npos) end = text.size();
      ++line_;
      parse_line(text.substr(start, end - start));
      start = end + 1;
    }
  }

  InputScript take() { return std::move(script_); }

 private:
  [[noreturn]] void fail(const std::string& message) const {
    throw InputScriptError(shown_path(script_.path) + ":" + std::to_string(line_) + ": " + message);
  }

  std::string_view token(std::size_t i) const { return tokens_[i]; }
  std::size_t arguments() const { return count_ - 3; }

  void parse_line(std::string_view line) {
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);  // CRLF
    if (const std::size_t hash = line.find('#'); hash != std::string_view::npos)
      line = line.substr(0, hash);
    split(line);
    if (count_ == 0) return;

    const double time = parse_time();
    if (count_ < 2) fail("missing target after the time (expected left, right or camera)");
    const std::string_view target = token(1);
    if (target == "left" || target == "right") {
      if (count_ < 3)
        fail("missing command for " + std::string(target) +
             " (expected hand, tool, jaw, clutch, pedal or power)");
      instrument_command(target == "left" ? 0 : 1, time);
    } else if (target == "camera") {
      if (count_ < 3) fail("missing command for camera (expected optics, insertion or roll)");
      camera_command(time);
    } else {
      fail("unknown target " + quoted(target) + " (expected left, right or camera)");
    }
    previous_time_ = time;
    previous_time_token_ = shown(token(0));
    any_line_ = true;
  }

  // Fields are separated by spaces and tabs; past kMaxTokens they are only counted (for the
  // message), so a line is never copied.
  void split(std::string_view line) {
    count_ = 0;
    std::size_t i = 0;
    while (i < line.size()) {
      while (i < line.size() && (line[i] == ' ' || line[i] == '\t'))
        ++i;
      if (i == line.size()) break;
      const std::size_t begin = i;
      while (i < line.size() && line[i] != ' ' && line[i] != '\t')
        ++i;
      if (count_ < kMaxTokens) tokens_[count_] = line.substr(begin, i - begin);
      ++count_;
    }
  }

  double parse_time() {
    double time = 0;
    const NumberStatus status = parse_number(token(0), time);
    if (status != NumberStatus::ok || time < 0)
      fail("time expects a finite number >= 0 (unit: s), got " + quoted(token(0)) +
           (status == NumberStatus::out_of_range ? " (out of range)" : ""));
    if (time > kMaxTime)
      fail("time " + shown(token(0)) + " s is after the limit of " + limit_text(kMaxTime) +
           " s (an hour); times are in seconds: was it written in milliseconds?");
    time += 0.0;  // -0 -> +0, so equal scripts give equal bits
    if (any_line_ && time < previous_time_)
      fail("time " + shown(token(0)) + " is earlier than the previous line's " +
           previous_time_token_);
    return time;
  }

  // The single argument of a command, as a number; `what` says what it expects.
  double number_argument(std::string_view command, const std::string& what) {
    if (arguments() != 1)
      fail(std::string(command) + " expects 1 argument (" + what + "), got " +
           std::to_string(arguments()));
    double value = 0;
    const NumberStatus status = parse_number(token(3), value);
    if (status != NumberStatus::ok)
      fail(std::string(command) + " expects a finite number (" + what + "), got " +
           quoted(token(3)) + (status == NumberStatus::out_of_range ? " (out of range)" : ""));
    return value;
  }

  // The single argument of a command, as one of `words` (its index); `expected` lists them.
  std::size_t word_argument(std::string_view command, std::initializer_list<std::string_view> words,
                            const std::string& expected) {
    if (arguments() != 1)
      fail(std::string(command) + " expects 1 argument (" + expected + "), got " +
           std::to_string(arguments()));
    std::size_t index = 0;
    for (const std::string_view w : words) {
      if (token(3) == w) return index;
      ++index;
    }
    fail(std::string(command) + " expects " + expected + ", got " + quoted(token(3)));
  }

  void check_range(std::string_view command, double value, double lo, double hi,
                   std::string_view unit) {
    if (value < lo || value > hi)
      fail(std::string(command) + " " + shown(token(3)) + " " + std::string(unit) + " is outside " +
           interval_text(lo, hi));
  }

  void instrument_command(std::size_t side, double time) {
    InstrumentTrack& track = side == 0 ? script_.left : script_.right;
    const std::string_view command = token(2);
    if (command == "hand" || command == "tool") {
      pose_command(side, track, command, time);
    } else if (command == "jaw") {
      static constexpr std::array<JawCommand, 3> kJaw = {JawCommand::open, JawCommand::close,
                                                         JawCommand::hold};
      const std::size_t i =
          word_argument(command, {"open", "close", "hold"}, "open, close or hold");
      track.jaw.push_back({time, kJaw[i]});
    } else if (command == "clutch") {
      const std::size_t i = word_argument(command, {"on", "off"}, "on or off");
      track.clutch.push_back({time, i == 0});
    } else if (command == "pedal") {
      static constexpr std::array<PedalMode, 3> kPedal = {PedalMode::off, PedalMode::cut,
                                                          PedalMode::coag};
      const std::size_t i = word_argument(command, {"off", "cut", "coag"}, "off, cut or coag");
      track.pedal.push_back({time, kPedal[i]});
    } else if (command == "power") {
      const double watts = number_argument(command, "unit: W");
      check_range(command, watts, kMinPower, kMaxPower, "W");
      track.power.push_back({time, Real(watts)});
    } else {
      fail("unknown command " + quoted(command) + " for " + std::string(token(1)) +
           " (expected hand, tool, jaw, clutch, pedal or power)");
    }
  }

  void pose_command(std::size_t side, InstrumentTrack& track, std::string_view command,
                    double time) {
    const PoseSource source = command == "hand" ? PoseSource::hand : PoseSource::tool;
    const std::string name(command);
    if (track.source != PoseSource::none && track.source != source) {
      const char* const other = track.source == PoseSource::hand ? "hand" : "tool";
      fail(std::string(token(1)) + " mixes " + name + " with " + other + " (" + other +
           " from line " + std::to_string(pose_line_[side]) +
           "); a target uses either hand or tool");
    }
    if (arguments() != 6)
      fail(name + " expects 6 numbers (x y z rx ry rz), got " + std::to_string(arguments()));

    static constexpr std::array<const char*, 6> kField = {"x", "y", "z", "rx", "ry", "rz"};
    std::array<double, 6> v{};
    for (std::size_t i = 0; i < 6; ++i) {
      const std::string_view text = token(3 + i);
      const NumberStatus status = parse_number(text, v[i]);
      const char* const unit = i < 3 ? "m" : "rad";
      if (status != NumberStatus::ok)
        fail(name + " " + kField[i] + " expects a finite number (unit: " + unit + "), got " +
             quoted(text) + (status == NumberStatus::out_of_range ? " (out of range)" : ""));
      // A bound far beyond any workspace catches millimetres typed as metres and keeps every
      // interpolated position finite.
      if (i < 3 && std::abs(v[i]) > kMaxCoordinate)
        fail(name + " " + kField[i] + " " + shown(text) + " m is outside " +
             interval_text(-kMaxCoordinate, kMaxCoordinate));
    }

    PoseKey key{time, Pose{}};
    key.pose.translation = Vec3(Real(v[0]), Real(v[1]), Real(v[2]));
    // Rotation vector: axis v/|v|, angle |v|. |v| is taken on v scaled by its largest
    // component, so components near the double limit do not overflow the norm.
    const Eigen::Vector3d r(v[3], v[4], v[5]);
    const double scale = r.cwiseAbs().maxCoeff();
    if (scale > 0) {
      const Eigen::Vector3d unit_scaled = r / scale;
      const double length = unit_scaled.norm();  // in [1, sqrt 3]
      const double angle = scale * length;
      if (!std::isfinite(angle))
        fail(name + " rotation vector (rx ry rz) is too long: its length overflows");
      // The same rotation with the angle in [-pi, pi]: accurate in float builds too.
      const double reduced = std::remainder(angle, kTwoPi);
      const Eigen::Matrix<Real, 3, 1> axis = (unit_scaled / length).cast<Real>();
      key.pose.rotation = Eigen::AngleAxis<Real>(Real(reduced), axis).toRotationMatrix();
    }
    if (track.source == PoseSource::none) {
      track.source = source;
      pose_line_[side] = line_;
    }
    track.poses.push_back(key);
  }

  void camera_command(double time) {
    CameraTrack& camera = script_.camera;
    const std::string_view command = token(2);
    if (command == "optics") {
      double degrees = 0;
      if (arguments() != 1)
        fail("optics expects 1 argument (0 or 30 degrees), got " + std::to_string(arguments()));
      if (parse_number(token(3), degrees) != NumberStatus::ok || (degrees != 0 && degrees != 30))
        fail("optics expects 0 or 30 (degrees), got " + quoted(token(3)));
      camera.optics.push_back({time, degrees_to_radians(Real(degrees + 0.0))});  // -0 -> +0
    } else if (command == "insertion") {
      const double metres = number_argument(command, "unit: m");
      check_range(command, metres, kMinInsertion, kMaxInsertion, "m");
      camera.insertion.push_back({time, Real(metres)});
    } else if (command == "roll") {
      const double radians = number_argument(command, "unit: rad");
      if (!fits_real(radians)) fail("roll " + shown(token(3)) + " rad is out of range");
      camera.roll.push_back({time, Real(radians)});
    } else {
      fail("unknown command " + quoted(command) +
           " for camera (expected optics, insertion or roll)");
    }
  }

  InputScript script_;
  std::size_t line_ = 0;  // 1-based, of the line being parsed
  std::array<std::string_view, kMaxTokens> tokens_{};
  std::size_t count_ = 0;  // tokens on the line, also those past kMaxTokens
  bool any_line_ = false;
  double previous_time_ = 0;                // (unit: s)
  std::string previous_time_token_;         // as written, for the message
  std::array<std::size_t, 2> pose_line_{};  // first pose line of left, right
};

// The last entry with time <= t, or null.
template <class T>
const T* last_at(const std::vector<Timed<T>>& keys, double t) {
  const auto it = std::upper_bound(keys.begin(), keys.end(), t,
                                   [](double x, const Timed<T>& k) { return x < k.time; });
  return it == keys.begin() ? nullptr : &std::prev(it)->value;
}

Pose pose_at(const std::vector<PoseKey>& keys, double t) {
  if (keys.empty()) return Pose{};
  // The first key after t; keys at equal times make a jump: the last of them holds from t on.
  const auto next = std::upper_bound(keys.begin(), keys.end(), t,
                                     [](double x, const PoseKey& k) { return x < k.time; });
  if (next == keys.begin()) return keys.front().pose;
  if (next == keys.end()) return keys.back().pose;
  const PoseKey& a = *std::prev(next);
  const PoseKey& b = *next;
  // b.time > a.time strictly (upper_bound), so no division by zero.
  const double s = std::clamp((t - a.time) / (b.time - a.time), 0.0, 1.0);
  if (s == 0) return a.pose;  // the key itself, bit for bit
  Pose p;
  // (1 - s) a + s b rather than a + s (b - a): exact at both ends and at the midpoint.
  p.translation = Real(1 - s) * a.pose.translation + Real(s) * b.pose.translation;
  const Eigen::Quaternion<Real> qa(a.pose.rotation), qb(b.pose.rotation);
  p.rotation = qa.slerp(Real(s), qb).normalized().toRotationMatrix();  // shortest way round
  return p;
}

}  // namespace

double InputScript::end_time() const {
  double end = 0;
  const auto last = [&end](const auto& keys) {
    if (!keys.empty()) end = std::max(end, keys.back().time);
  };
  for (const InstrumentTrack* track : {&left, &right}) {
    last(track->poses);
    last(track->jaw);
    last(track->clutch);
    last(track->pedal);
    last(track->power);
  }
  last(camera.optics);
  last(camera.insertion);
  last(camera.roll);
  return end;
}

InputScript parse_input_script(std::string_view text, const std::string& path) {
  Parser parser(path);
  parser.parse(text);
  return parser.take();
}

InputScript load_input_script(const std::string& path) {
  const TextFile file = read_text_file(path, kMaxScriptBytes, "input script");
  if (!file.error.empty()) throw InputScriptError(shown_path(path) + ": " + file.error);
  return parse_input_script(file.text, path);
}

InstrumentInput sample_instrument(const InstrumentTrack& track, double t) {
  InstrumentInput in;
  in.source = track.poses.empty() ? PoseSource::none : track.source;
  in.pose = pose_at(track.poses, t);
  if (const JawCommand* jaw = last_at(track.jaw, t)) in.jaw = *jaw;
  if (const bool* clutch = last_at(track.clutch, t)) in.clutch = *clutch;
  if (const PedalMode* pedal = last_at(track.pedal, t)) in.pedal = *pedal;
  if (const Real* power = last_at(track.power, t)) in.power = *power;
  return in;
}

CameraInput sample_camera(const CameraTrack& track, double t) {
  CameraInput in;
  if (const Real* optics = last_at(track.optics, t)) in.optics = *optics;
  if (const Real* insertion = last_at(track.insertion, t)) in.insertion = *insertion;
  if (const Real* roll = last_at(track.roll, t)) in.roll = *roll;
  return in;
}

}  // namespace imasim::surgery
