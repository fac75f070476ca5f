#include "metrics/threshold_file.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>

#include "math/edit_distance.hpp"
#include "math/printable.hpp"
#include "math/text_file.hpp"
#include "metrics/trainee_metrics.hpp"

namespace imasim::metrics {

namespace {

std::size_t line_at(const std::string& text, std::size_t byte) {
  byte = std::min(byte, text.size());
  return std::size_t(std::count(text.begin(), text.begin() + std::ptrdiff_t(byte), '\n')) + 1;
}

// The line of a key's first appearance as a JSON string in the text (1 if not found).
std::size_t line_of_key(const std::string& text, const std::string& key) {
  const std::size_t at = text.find(nlohmann::json(key).dump());
  return at == std::string::npos ? 1 : line_at(text, at);
}

}  // namespace

std::map<std::string, double> parse_threshold_file(const std::string& text,
                                                   const std::string& path) {
  nlohmann::json j;
  try {
    j = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw ThresholdFileError(path + ":" + std::to_string(line_at(text, e.byte)) +
                             ": not JSON: " + printable(e.what(), 160));
  }
  if (!j.is_object())
    throw ThresholdFileError(path + ":1: expected a JSON object of metric names to thresholds");
  const std::vector<std::string> names = trainee_metric_names();
  std::map<std::string, double> out;
  for (auto it = j.begin(); it != j.end(); ++it) {
    const std::string& key = it.key();
    const std::string where = path + ":" + std::to_string(line_of_key(text, key)) + ": ";
    if (std::find(names.begin(), names.end(), key) == names.end()) {
      std::string nearest = names.front();
      for (const std::string& n : names)
        if (edit_distance(key, n) < edit_distance(key, nearest)) nearest = n;
      throw ThresholdFileError(where + "'" + printable(key, 60) + "' is no metric; did you mean '" +
                               nearest + "'?");
    }
    if (!it->is_number() || !std::isfinite(it->get<double>()))
      throw ThresholdFileError(where + "'" + key + "': expected a finite number, got " +
                               printable(it->dump(), 60));
    out[key] = it->get<double>();
  }
  return out;
}

std::map<std::string, double> load_threshold_file(const std::string& path) {
  const TextFile file = read_text_file(path, kMaxThresholdFileBytes, "thresholds file");
  if (!file.error.empty()) throw ThresholdFileError(path + ": " + file.error);
  return parse_threshold_file(file.text, path);
}

}  // namespace imasim::metrics
