#pragma once
// What a study is made of, as its report reads it: what was run (StudyInfo) and one result per
// trial (TrialResult: its status and, when it finished, the scores its recording's side file
// holds). The experiment command fills these; the statistics and the writers only read them.
#include <cstdint>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace imasim::report {

class StudyDataError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The study's headline SAI is the dissecting instrument's: the cautery hook (the paper's Table 1).
inline constexpr const char* kHeadlineInstrument = "hook";
inline constexpr const char* kInstruments[] = {"forceps", "hook"};

struct SaiValue {
  double sai = 0;              // eq. 20, dimensionless
  std::uint64_t samples = 0;   // n of eq. 20
  double mean_distance_m = 0;  // mean |d_i| (unit: m)
  double heart_side_fraction = 0;
};

struct MetricValue {
  std::string name, unit;
  double value = 0;
  double threshold = 0;
  bool higher_is_better = false;
  bool pass = false;
};

struct TrialResult {
  std::string mode;  // "dynamic" or "static"
  int trial = 0;     // 1-based; trial k has the same patient in every mode
  std::uint64_t patient_seed = 0;
  std::optional<std::uint64_t> operator_seed;  // the scripted operator's; unset for an input script
  bool ok = false;
  std::string reason;                            // why it failed (empty when ok)
  double wall_s = 0;                             // wall-clock time it ran (unit: s)
  std::map<std::string, std::string> files;      // "recording", "side", "report", "log" -> path
  std::map<std::string, SaiValue> sai;           // by instrument
  std::vector<MetricValue> metrics;              // in the run's order
  std::map<std::string, std::string> heat_maps;  // by instrument: a PNG file
  std::map<std::string, std::string> views;      // the scene drawn: "start", "end" -> PNG file
};

struct StudyInfo {
  std::string program;  // "imasim 0.14.0"
  std::string scene;    // "built-in thorax"
  std::vector<std::string> modes;
  int trials_per_mode = 0;
  std::uint64_t seed = 0;
  std::string operator_kind;         // "autopilot" or "script"
  std::string operator_description;  // a sentence for the report's header
  std::string script;                // the input script (operator_kind "script")
  std::optional<double> seconds;     // simulated time asked of each trial (unit: s)
  int jobs = 1;
  double trial_timeout_s = 0;  // 0: none
  std::string date;            // ISO 8601, UTC
  std::string status;          // "complete" or "interrupted"
};

// An image the report embeds beside the heat maps (a plot of another helper).
struct ReportImage {
  std::string caption;
  std::string png_path;
};

// A table the report shows with those images (the trainee's history): its cells as text.
struct ReportTable {
  std::string caption;
  std::vector<std::string> header;
  std::vector<std::vector<std::string>> rows;
};

// Fills `trial`'s scores (SAI per instrument, metrics, heat maps) from a run's recording side
// file (its JSON text `text`, read from `path`). Throws StudyDataError naming the file and the
// key when the scores are missing or malformed.
void read_trial_scores(const std::string& text, const std::string& path, TrialResult& trial);

}  // namespace imasim::report
