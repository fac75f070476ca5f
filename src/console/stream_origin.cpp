#include "console/stream_origin.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "console/input_stream.hpp"
#include "math/printable.hpp"
#include "math/state_hash.hpp"
#include "scene/scene_file.hpp"

namespace imasim::console {

namespace {

std::string hex_double(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%a", v);
  return buffer;
}

constexpr std::size_t kFields = 8;
// The named fields first; the scene's hash last, for what the others do not name.
constexpr const char* kNames[kFields] = {"program",        "patient_seed", "heart",
                                         "dt_s",           "substeps",     "iterations",
                                         "stretch_sweeps", "scene_hash"};

std::string value_of(const StreamOrigin& o, std::size_t field) {
  switch (field) {
    case 0:
      return o.program;
    case 1:
      return std::to_string(o.patient_seed);
    case 2:
      return o.heart;
    case 3:
      return hex_double(o.dt_s);
    case 4:
      return std::to_string(o.substeps);
    case 5:
      return std::to_string(o.iterations);
    case 6:
      return std::to_string(o.stretch_sweeps);
    default:
      return o.scene_hash;
  }
}

// Sets one field from its text; false when the text is not a value of it.
bool set_field(StreamOrigin& o, std::size_t field, const std::string& text) {
  char* end = nullptr;
  switch (field) {
    case 0:
      o.program = text;
      return !text.empty();
    case 7:
      o.scene_hash = text;
      return text.size() == 16 && text.find_first_not_of("0123456789abcdef") == std::string::npos;
    case 2:
      o.heart = text;
      return text == "beating" || text == "static";
    case 3:
      o.dt_s = std::strtod(text.c_str(), &end);
      return end == text.c_str() + text.size() && o.dt_s > 0;
    default:
      break;
  }
  if (text.empty() || text.size() > 20 || text.find_first_not_of("0123456789") != std::string::npos)
    return false;
  errno = 0;
  const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
  if (errno == ERANGE) return false;
  if (field == 1) {
    o.patient_seed = v;
    return true;
  }
  if (v > 1'000'000) return false;
  (field == 4 ? o.substeps : field == 5 ? o.iterations : o.stretch_sweeps) = std::uint32_t(v);
  return true;
}

}  // namespace

StreamOrigin stream_origin_of(const scene::ThoraxSceneParams& params, std::string program) {
  StreamOrigin o;
  o.program = std::move(program);
  const std::string scene = scene::print_scene(params);
  o.scene_hash = to_hex(hash_bytes(scene.data(), scene.size()));
  o.patient_seed = params.anatomy.patient_seed;
  o.heart = params.playback.beating ? "beating" : "static";
  o.dt_s = double(params.patch.solver.dt);
  o.substeps = params.patch.solver.substeps;
  o.iterations = params.patch.solver.iterations;
  o.stretch_sweeps = params.patch.solver.stretch_sweeps;
  return o;
}

std::string format_stream_origin(const StreamOrigin& o) {
  std::string out;
  for (std::size_t k = 0; k < kFields; ++k)
    out += std::string("#! ") + kNames[k] + " " + value_of(o, k) + "\n";
  return out;
}

std::string format_stream_end(std::uint64_t steps) {
  return "#! end " + std::to_string(steps) + "\n";
}

StreamHead read_stream_head(std::string_view text, const std::string& path) {
  StreamHead head;
  StreamOrigin o;
  bool seen[kFields] = {};
  std::size_t line_number = 0, given = 0;
  while (!text.empty()) {
    const std::size_t cut = text.find('\n');
    std::string_view line = text.substr(0, cut);
    text = cut == std::string_view::npos ? std::string_view() : text.substr(cut + 1);
    ++line_number;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!line.starts_with("#!")) continue;
    const std::string where = path + ":" + std::to_string(line_number) + ": ";
    std::istringstream words{std::string(line.substr(2))};
    std::string key, value, extra;
    words >> key >> value;
    if (key.empty() || value.empty() || (words >> extra))
      throw InputStreamError(where + "expected '#! KEY VALUE'");
    if (head.end_steps) throw InputStreamError(where + "a line after the stream's end line");
    if (key == "end") {
      StreamOrigin scratch;
      if (!set_field(scratch, 1, value))
        throw InputStreamError(where + "the end line's step count is not a count");
      head.end_steps = std::strtoull(value.c_str(), nullptr, 10);
      continue;
    }
    std::size_t field = kFields;
    for (std::size_t k = 0; k < kFields; ++k)
      if (key == kNames[k]) field = k;
    if (field == kFields)
      throw InputStreamError(where + "unknown origin field '" + printable(key, 40) + "'");
    if (seen[field]) throw InputStreamError(where + "'" + key + "' given twice");
    if (!set_field(o, field, value))
      throw InputStreamError(where + "'" + key + "': not a value of it ('" + printable(value, 40) +
                             "')");
    seen[field] = true;
    ++given;
  }
  if (given > 0 && given < kFields) {
    for (std::size_t k = 0; k < kFields; ++k)
      if (!seen[k])
        throw InputStreamError(path + ": the stream's origin has no '" + kNames[k] + "' line");
  }
  if (given == kFields) head.origin = o;
  return head;
}

std::vector<std::string> origin_differences(const StreamOrigin& recorded, const StreamOrigin& now) {
  std::vector<std::string> out;
  for (std::size_t k = 0; k < kFields; ++k) {
    const std::string a = value_of(recorded, k), b = value_of(now, k);
    if (a != b) out.push_back(std::string(kNames[k]) + ": recorded " + a + ", this run " + b);
  }
  return out;
}

}  // namespace imasim::console
