#include "console/input_stream.hpp"

#include <cmath>
#include <cstdlib>
#include <sstream>

#include "math/text_file.hpp"

namespace imasim::console {

namespace {

// The longest stream read: two hours of 5 ms steps (lines are about 600 bytes).
constexpr std::size_t kMaxSteps = 1'440'000;
constexpr std::uint64_t kMaxStreamBytes = std::uint64_t(1) << 30;

void put(std::string& out, double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, " %a", v);
  out += buffer;
}

const char* source_name(surgery::PoseSource s) {
  switch (s) {
    case surgery::PoseSource::hand:
      return "hand";
    case surgery::PoseSource::tool:
      return "tool";
    case surgery::PoseSource::none:
      break;
  }
  return "none";
}

const char* pedal_name(surgery::PedalMode p) {
  switch (p) {
    case surgery::PedalMode::cut:
      return "cut";
    case surgery::PedalMode::coag:
      return "coag";
    case surgery::PedalMode::off:
      break;
  }
  return "off";
}

void put_instrument(std::string& out, const surgery::InstrumentInput& in) {
  out += ' ';
  out += source_name(in.source);
  for (int i = 0; i < 3; ++i)
    put(out, double(in.pose.translation(i)));
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      put(out, double(in.pose.rotation(i, j)));
  out += ' ' + std::to_string(int(in.jaw)) + (in.clutch ? " 1 " : " 0 ") + pedal_name(in.pedal);
  put(out, double(in.power));
}

// Reads the fields of one line in order, naming the field that is wrong.
class Fields {
 public:
  Fields(std::string_view line, const std::string& where) : where_(where) {
    std::istringstream in{std::string(line)};
    for (std::string f; in >> f;)
      fields_.push_back(f);
  }
  std::size_t size() const { return fields_.size(); }
  [[noreturn]] void fail(const std::string& what) const {
    throw InputStreamError(where_ + ": " + what);
  }
  const std::string& next(const char* name) {
    if (at_ >= fields_.size()) fail(std::string("missing ") + name);
    return fields_[at_++];
  }
  double number(const char* name) {
    const std::string& f = next(name);
    char* end = nullptr;
    const double v = std::strtod(f.c_str(), &end);
    if (end == f.c_str() || *end != '\0' || !std::isfinite(v))
      fail(std::string(name) + " '" + f + "' is not a finite number");
    return v;
  }
  bool done() const { return at_ == fields_.size(); }

 private:
  std::string where_;
  std::vector<std::string> fields_;
  std::size_t at_ = 0;
};

surgery::InstrumentInput read_instrument(Fields& f, const char* hand) {
  surgery::InstrumentInput in;
  const std::string& source = f.next("pose source");
  if (source == "hand")
    in.source = surgery::PoseSource::hand;
  else if (source == "tool")
    in.source = surgery::PoseSource::tool;
  else if (source != "none")
    f.fail(std::string(hand) + " pose source '" + source + "' is not none, hand or tool");
  for (int i = 0; i < 3; ++i)
    in.pose.translation(i) = Real(f.number("position"));
  if (in.pose.translation.cwiseAbs().maxCoeff() > 10)
    f.fail(std::string(hand) + " position is more than 10 m away");
  Mat3 r;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      r(i, j) = Real(f.number("rotation"));
  if (!((r.transpose() * r - Mat3::Identity()).cwiseAbs().maxCoeff() < Real(1e-6)) ||
      !(r.determinant() > 0))
    f.fail(std::string(hand) + " rotation is not a rotation");
  in.pose.rotation = r;
  const std::string& jaw = f.next("jaw");
  if (jaw == "-1")
    in.jaw = surgery::JawCommand::close;
  else if (jaw == "1")
    in.jaw = surgery::JawCommand::open;
  else if (jaw != "0")
    f.fail(std::string(hand) + " jaw '" + jaw + "' is not -1, 0 or 1");
  const std::string& clutch = f.next("clutch");
  if (clutch != "0" && clutch != "1")
    f.fail(std::string(hand) + " clutch '" + clutch + "' is not 0 or 1");
  in.clutch = clutch == "1";
  const std::string& pedal = f.next("pedal");
  if (pedal == "cut")
    in.pedal = surgery::PedalMode::cut;
  else if (pedal == "coag")
    in.pedal = surgery::PedalMode::coag;
  else if (pedal != "off")
    f.fail(std::string(hand) + " pedal '" + pedal + "' is not off, cut or coag");
  const double power = f.number("power");
  if (power < 0 || power > 300) f.fail(std::string(hand) + " power is outside 0 .. 300 W");
  in.power = Real(power);
  return in;
}

}  // namespace

std::string format_input_line(std::uint64_t step, const session::SessionInput& in) {
  std::string out = std::to_string(step);
  put_instrument(out, in.left);
  put_instrument(out, in.right);
  put(out, double(in.camera.optics));
  if (in.camera.insertion)
    put(out, double(*in.camera.insertion));
  else
    out += " -";
  if (in.camera.roll)
    put(out, double(*in.camera.roll));
  else
    out += " -";
  // Only on the steps of a lost device: streams of sessions without one read as before.
  if (in.left.device_lost || in.right.device_lost)
    out += in.left.device_lost && in.right.device_lost ? " lost:both"
           : in.left.device_lost                       ? " lost:left"
                                                       : " lost:right";
  return out;
}

std::vector<session::SessionInput> parse_input_stream(std::string_view text,
                                                      const std::string& path) {
  std::vector<session::SessionInput> steps;
  std::size_t line_number = 0;
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    const std::string_view line = text.substr(0, end);
    text = end == std::string_view::npos ? std::string_view() : text.substr(end + 1);
    ++line_number;
    Fields f(line, path + ":" + std::to_string(line_number));
    if (f.size() == 0 || f.next("step")[0] == '#') continue;
    Fields g(line, path + ":" + std::to_string(line_number));
    const double step = g.number("step");
    if (step != double(steps.size())) {
      char shown[32];
      std::snprintf(shown, sizeof shown, "%.0f", step);
      g.fail(std::string("step ") + shown + " out of order; expected " +
             std::to_string(steps.size()));
    }
    if (steps.size() >= kMaxSteps) g.fail("more than " + std::to_string(kMaxSteps) + " steps");
    session::SessionInput in;
    in.left = read_instrument(g, "left");
    in.right = read_instrument(g, "right");
    in.camera.optics = Real(g.number("camera optics"));
    const std::string insertion = g.next("camera insertion");
    if (insertion != "-") {
      Fields h(insertion, path + ":" + std::to_string(line_number));
      in.camera.insertion = Real(h.number("camera insertion"));
    }
    const std::string roll = g.next("camera roll");
    if (roll != "-") {
      Fields h(roll, path + ":" + std::to_string(line_number));
      in.camera.roll = Real(h.number("camera roll"));
    }
    if (!g.done()) {
      const std::string lost = g.next("lost devices");
      if (lost == "lost:left" || lost == "lost:both") in.left.device_lost = true;
      if (lost == "lost:right" || lost == "lost:both") in.right.device_lost = true;
      if (!in.left.device_lost && !in.right.device_lost)
        g.fail("unexpected fields after the camera's ('" + lost +
               "'; only lost:left, lost:right or lost:both may follow)");
    }
    if (!g.done()) g.fail("unexpected fields after the camera's");
    steps.push_back(in);
  }
  return steps;
}

std::vector<session::SessionInput> load_input_stream(const std::string& path) {
  const TextFile file = read_text_file(path, kMaxStreamBytes, "input stream");
  if (!file.error.empty()) throw InputStreamError(path + ": " + file.error);
  return parse_input_stream(file.text, path);
}

RecordedStream load_recorded_stream(const std::string& path) {
  const TextFile file = read_text_file(path, kMaxStreamBytes, "input stream");
  if (!file.error.empty()) throw InputStreamError(path + ": " + file.error);
  RecordedStream s;
  s.head = read_stream_head(file.text, path);
  s.steps = parse_input_stream(file.text, path);
  return s;
}

}  // namespace imasim::console
