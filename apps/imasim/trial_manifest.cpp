#include "trial_manifest.hpp"

#include <nlohmann/json.hpp>

#include "math/state_hash.hpp"
#include "math/text_file.hpp"
#include "metrics/output_file.hpp"

namespace imasim::cli {

namespace {

// A trial's recording is a few MB a minute; a file larger than this is no trial's.
constexpr std::uint64_t kMaxTrialFileBytes = std::uint64_t(1) << 30;

// FNV-1a of the file's bytes as 16 hex digits; empty when it cannot be read.
std::string file_hash(const std::string& path) {
  const TextFile f = read_text_file(path, kMaxTrialFileBytes, "trial file");
  if (!f.error.empty()) return {};
  return to_hex(hash_bytes(f.text.data(), f.text.size()));
}

std::vector<std::pair<std::string, std::string>> trial_files(const TrialPlan& plan) {
  return {{"recording", plan.recording}, {"side", plan.side}, {"report", plan.report}};
}

}  // namespace

std::string manifest_path(const TrialPlan& plan) {
  const std::string suffix = ".report.json";
  std::string stem = plan.report;
  if (stem.ends_with(suffix)) stem.resize(stem.size() - suffix.size());
  return stem + ".done.json";
}

void write_trial_manifest(const TrialPlan& plan, const std::vector<std::string>& arguments,
                          double wall_s) {
  nlohmann::ordered_json j;
  j["arguments"] = arguments;
  j["wall_s"] = wall_s;
  nlohmann::ordered_json files;
  for (const auto& [name, path] : trial_files(plan))
    files[name] = {{"path", path}, {"fnv1a64", file_hash(path)}};
  j["files"] = files;
  metrics::OutputFile out(manifest_path(plan), "the trial's manifest");
  out.write(j.dump(2) + "\n");
  out.close();
}

std::optional<double> kept_trial(const TrialPlan& plan, const std::vector<std::string>& arguments) {
  const TextFile text = read_text_file(manifest_path(plan), 1 << 20, "trial's manifest");
  if (!text.error.empty()) return std::nullopt;
  const nlohmann::json j = nlohmann::json::parse(text.text, nullptr, false);
  if (!j.is_object() || !j.contains("arguments") || !j.contains("files") || !j.contains("wall_s") ||
      !j["wall_s"].is_number())
    return std::nullopt;
  if (j["arguments"] != nlohmann::json(arguments)) return std::nullopt;
  for (const auto& [name, path] : trial_files(plan)) {
    const nlohmann::json& f = j["files"].value(name, nlohmann::json());
    if (!f.is_object() || f.value("path", "") != path) return std::nullopt;
    const std::string recorded = f.value("fnv1a64", "");
    if (recorded.empty() || recorded != file_hash(path)) return std::nullopt;
  }
  return j["wall_s"].get<double>();
}

}  // namespace imasim::cli
