#include <filesystem>
#include <nlohmann/json.hpp>

#include "report/study_data.hpp"

namespace imasim::report {

namespace {

using Json = nlohmann::json;

[[noreturn]] void fail(const std::string& path, const std::string& key, const std::string& why) {
  throw StudyDataError(path + ": key \"" + key + "\": " + why);
}

const Json& member(const Json& object, const std::string& name, const std::string& path,
                   const std::string& key) {
  if (!object.is_object() || !object.contains(name)) fail(path, key, "missing");
  return object.at(name);
}

double number(const Json& object, const std::string& name, const std::string& path,
              const std::string& key) {
  const Json& v = member(object, name, path, key + "." + name);
  if (!v.is_number()) fail(path, key + "." + name, "not a number");
  return v.get<double>();
}

bool flag(const Json& object, const std::string& name, const std::string& path,
          const std::string& key) {
  const Json& v = member(object, name, path, key + "." + name);
  if (!v.is_boolean()) fail(path, key + "." + name, "not true or false");
  return v.get<bool>();
}

std::string text(const Json& object, const std::string& name, const std::string& path,
                 const std::string& key) {
  const Json& v = member(object, name, path, key + "." + name);
  if (!v.is_string()) fail(path, key + "." + name, "not a string");
  return v.get<std::string>();
}

// A relative heat map path is taken from the side file's folder when it is there.
std::string image_path(const std::string& given, const std::string& side_path) {
  const std::filesystem::path p(given);
  if (p.is_absolute()) return given;
  const std::filesystem::path beside = std::filesystem::path(side_path).parent_path() / p;
  std::error_code ec;
  return std::filesystem::exists(beside, ec) ? beside.string() : given;
}

// The plotting step adds "heat_maps": {"forceps": PATH, "hook": PATH}; it is looked for beside
// the scores, in the run and at the top of the side file.
const Json* heat_map_object(const Json& side, const Json& run, const Json& scores) {
  for (const Json* where : {&scores, &run, &side})
    if (where->contains("heat_maps")) return &where->at("heat_maps");
  return nullptr;
}

}  // namespace

void read_trial_scores(const std::string& body, const std::string& path, TrialResult& trial) {
  const Json side = Json::parse(body, nullptr, false);
  if (side.is_discarded()) throw StudyDataError(path + ": not a JSON document");
  const Json& run = member(side, "run", path, "run");
  const Json& scores = member(run, "scores", path, "run.scores");
  const Json& sai = member(scores, "sai", path, "run.scores.sai");
  for (const char* tool : kInstruments) {
    const std::string key = std::string("run.scores.sai.") + tool;
    const Json& s = member(sai, tool, path, key);
    SaiValue v;
    v.sai = number(s, "sai", path, key);
    const double samples = number(s, "samples", path, key);
    if (samples < 0) fail(path, key + ".samples", "negative");
    v.samples = static_cast<std::uint64_t>(samples);
    v.mean_distance_m = number(s, "mean_distance_m", path, key);
    v.heart_side_fraction = number(s, "heart_side_fraction", path, key);
    trial.sai[tool] = v;
  }
  const Json& list = member(scores, "metrics", path, "run.scores.metrics");
  if (!list.is_array()) fail(path, "run.scores.metrics", "not a list");
  trial.metrics.clear();
  for (std::size_t i = 0; i < list.size(); ++i) {
    const std::string key = "run.scores.metrics[" + std::to_string(i) + "]";
    const Json& m = list[i];
    MetricValue v;
    v.name = text(m, "name", path, key);
    v.unit = text(m, "unit", path, key);
    v.value = number(m, "value", path, key);
    v.threshold = number(m, "threshold", path, key);
    const std::string better = text(m, "better", path, key);
    if (better != "higher" && better != "lower") fail(path, key + ".better", "not higher or lower");
    v.higher_is_better = better == "higher";
    v.pass = flag(m, "pass", path, key);
    trial.metrics.push_back(v);
  }
  trial.heat_maps.clear();
  if (const Json* maps = heat_map_object(side, run, scores)) {
    if (!maps->is_object()) fail(path, "heat_maps", "not an object of instrument to PNG file");
    for (auto it = maps->begin(); it != maps->end(); ++it) {
      if (!it->is_string()) fail(path, "heat_maps." + it.key(), "not a file name");
      trial.heat_maps[it.key()] = image_path(it->get<std::string>(), path);
    }
  }
  // Pictures of the scene (optional: a machine without OpenGL records without them).
  trial.views.clear();
  if (run.contains("views")) {
    const Json& views = run.at("views");
    if (!views.is_object()) fail(path, "run.views", "not an object of moment to PNG file");
    for (auto it = views.begin(); it != views.end(); ++it) {
      if (!it->is_string()) fail(path, "run.views." + it.key(), "not a file name");
      trial.views[it.key()] = image_path(it->get<std::string>(), path);
    }
  }
}

}  // namespace imasim::report
