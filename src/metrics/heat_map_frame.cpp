#include "metrics/heat_map_frame.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "math/printable.hpp"
#include "math/text_file.hpp"
#include "metrics/output_file.hpp"

namespace imasim::metrics {

namespace {

constexpr const char* kFormat = "imasim heat map frame";
constexpr int kVersion = 1;
constexpr double kUnitTolerance = 1e-6;

bool finite(const Vec3& p) {
  return std::isfinite(double(p.x())) && std::isfinite(double(p.y())) &&
         std::isfinite(double(p.z()));
}

nlohmann::ordered_json json_of(const Vec3& p) {
  return nlohmann::ordered_json::array({double(p.x()), double(p.y()), double(p.z())});
}

nlohmann::ordered_json json_of(std::span<const Vec3> points) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (const Vec3& p : points)
    out.push_back(json_of(p));
  return out;
}

// Reading: every error names the file and the key path.
class FrameReader {
 public:
  explicit FrameReader(std::string path) : path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw HeatMapFrameError(path_ + ": key '" + key + "': " + what);
  }

  const nlohmann::json& member(const nlohmann::json& object, const std::string& name,
                               const std::string& key) const {
    const auto it = object.find(name);
    if (it == object.end()) fail(key, "missing");
    return *it;
  }

  Vec3 point(const nlohmann::json& j, const std::string& key) const {
    if (!j.is_array() || j.size() != 3) fail(key, "expected [x, y, z], got " + shown(j));
    Vec3 p;
    for (std::size_t k = 0; k < 3; ++k) {
      if (!j[k].is_number() || !std::isfinite(j[k].get<double>()))
        fail(key, "expected three finite numbers (m), got " + shown(j));
      p[Eigen::Index(k)] = Real(j[k].get<double>());
    }
    return p;
  }

  std::vector<Vec3> points(const nlohmann::json& j, const std::string& key) const {
    if (!j.is_array() || j.empty()) fail(key, "expected a non-empty list of [x, y, z]");
    std::vector<Vec3> out;
    out.reserve(j.size());
    for (std::size_t i = 0; i < j.size(); ++i)
      out.push_back(point(j[i], key + "[" + std::to_string(i) + "]"));
    return out;
  }

  std::array<double, 3> colour(const nlohmann::json& j, const std::string& key) const {
    std::array<double, 3> rgb{};
    if (!j.is_array() || j.size() != 3)
      fail(key, "expected three numbers in [0, 1], got " + shown(j));
    for (std::size_t k = 0; k < 3; ++k) {
      if (!j[k].is_number()) fail(key, "expected three numbers in [0, 1], got " + shown(j));
      rgb[k] = j[k].get<double>();
      if (!(rgb[k] >= 0 && rgb[k] <= 1))
        fail(key, "expected three numbers in [0, 1], got " + shown(j));
    }
    return rgb;
  }

  static std::string shown(const nlohmann::json& j) { return printable(j.dump(), 60); }

 private:
  std::string path_;
};

std::size_t line_at(const std::string& text, std::size_t byte) {
  byte = std::min(byte, text.size());
  return std::size_t(std::count(text.begin(), text.begin() + std::ptrdiff_t(byte), '\n')) + 1;
}

}  // namespace

PlanePoint project(const HeatMapFrame& f, const Vec3& p) {
  const Vec3 d = p - f.origin;
  return {double(d.dot(f.u)), double(d.dot(f.v))};
}

std::vector<PlanePoint> project(const HeatMapFrame& f, std::span<const Vec3> points) {
  std::vector<PlanePoint> out;
  out.reserve(points.size());
  for (const Vec3& p : points)
    out.push_back(project(f, p));
  return out;
}

void check_heat_map_frame(const HeatMapFrame& f, const std::string& where) {
  const auto fail = [&](const std::string& key, const std::string& what) {
    throw HeatMapFrameError(where + ": key '" + key + "': " + what);
  };
  if (!finite(f.origin)) fail("origin", "not finite");
  if (!finite(f.u)) fail("u", "not finite");
  if (!finite(f.v)) fail("v", "not finite");
  if (std::abs(double(f.u.norm()) - 1) > kUnitTolerance) fail("u", "not of unit length");
  if (std::abs(double(f.v.norm()) - 1) > kUnitTolerance) fail("v", "not of unit length");
  if (std::abs(double(f.u.dot(f.v))) > kUnitTolerance) fail("v", "not perpendicular to u");
  for (std::size_t i = 0; i < f.centerline.size(); ++i)
    if (!finite(f.centerline[i])) fail("centerline[" + std::to_string(i) + "]", "not finite");
  for (std::size_t k = 0; k < f.outlines.size(); ++k) {
    const HeatMapOutline& o = f.outlines[k];
    const std::string key = "outlines[" + std::to_string(k) + "]";
    if (o.points.empty()) fail(key + ".points", "no points");
    for (std::size_t i = 0; i < o.points.size(); ++i)
      if (!finite(o.points[i])) fail(key + ".points[" + std::to_string(i) + "]", "not finite");
    for (double c : o.rgb)
      if (!(c >= 0 && c <= 1)) fail(key + ".rgb", "outside [0, 1]");
  }
}

std::string heat_map_frame_json(const HeatMapFrame& f) {
  nlohmann::ordered_json j;
  j["format"] = kFormat;
  j["version"] = kVersion;
  j["units"] = "m";
  j["meaning"] =
      "a point p projects to ((p - origin) . u, (p - origin) . v); u along the IMA, v across it";
  j["origin"] = json_of(f.origin);
  j["u"] = json_of(f.u);
  j["v"] = json_of(f.v);
  j["centerline"] = json_of(f.centerline);
  nlohmann::ordered_json outlines = nlohmann::ordered_json::array();
  for (const HeatMapOutline& o : f.outlines)
    outlines.push_back(
        {{"name", o.name}, {"rgb", o.rgb}, {"closed", o.closed}, {"points", json_of(o.points)}});
  j["outlines"] = outlines;
  return j.dump(1) + '\n';
}

HeatMapFrame parse_heat_map_frame(const std::string& text, const std::string& path) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw HeatMapFrameError(path + ":" + std::to_string(line_at(text, e.byte)) +
                            ": not JSON: " + printable(e.what(), 160));
  }
  const FrameReader r(path);
  if (!j.is_object()) throw HeatMapFrameError(path + ": expected a JSON object (a heat map frame)");
  const nlohmann::json& format = r.member(j, "format", "format");
  if (format != kFormat) r.fail("format", "expected \"" + std::string(kFormat) + "\"");
  const nlohmann::json& version = r.member(j, "version", "version");
  if (version != kVersion) r.fail("version", "expected " + std::to_string(kVersion));
  HeatMapFrame f;
  f.origin = r.point(r.member(j, "origin", "origin"), "origin");
  f.u = r.point(r.member(j, "u", "u"), "u");
  f.v = r.point(r.member(j, "v", "v"), "v");
  f.centerline = r.points(r.member(j, "centerline", "centerline"), "centerline");
  const nlohmann::json& outlines = r.member(j, "outlines", "outlines");
  if (!outlines.is_array()) r.fail("outlines", "expected a list");
  for (std::size_t k = 0; k < outlines.size(); ++k) {
    const std::string key = "outlines[" + std::to_string(k) + "]";
    const nlohmann::json& o = outlines[k];
    if (!o.is_object()) r.fail(key, "expected an object");
    HeatMapOutline out;
    const nlohmann::json& name = r.member(o, "name", key + ".name");
    if (!name.is_string() || name.get<std::string>().empty())
      r.fail(key + ".name", "expected a non-empty text");
    out.name = name.get<std::string>();
    out.rgb = r.colour(r.member(o, "rgb", key + ".rgb"), key + ".rgb");
    const nlohmann::json& closed = r.member(o, "closed", key + ".closed");
    if (!closed.is_boolean()) r.fail(key + ".closed", "expected true or false");
    out.closed = closed.get<bool>();
    out.points = r.points(r.member(o, "points", key + ".points"), key + ".points");
    f.outlines.push_back(std::move(out));
  }
  check_heat_map_frame(f, path);
  return f;
}

void write_heat_map_frame(const HeatMapFrame& f, const std::string& path,
                          std::span<const std::string> inputs) {
  check_heat_map_frame(f, path);
  OutputFile file(path, "the heat map frame", inputs);
  file.write(heat_map_frame_json(f));
  file.close();
}

HeatMapFrame read_heat_map_frame(const std::string& path) {
  const TextFile file = read_text_file(path, kMaxHeatMapFrameBytes, "heat map frame");
  if (!file.error.empty()) throw HeatMapFrameError(path + ": " + file.error);
  return parse_heat_map_frame(file.text, path);
}

}  // namespace imasim::metrics
