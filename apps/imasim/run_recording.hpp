#pragma once
// `imasim run --record FILE.csv`: the session's trajectory at 60 Hz in FILE.csv
// (metrics/trajectory_recorder.hpp), a side file FILE.json (what was run, the columns' units and
// meanings; written at the start so that a killed run still has it, and again at the end with
// how the run ended and its scores), the events in FILE.events.csv unless --events names another
// file, and what `imasim sai` needs to score the recording again: the IMA's centerline
// (FILE.centerline.csv) and the heart at its static phase (FILE.heart.obj), from which the run
// scores each instrument's tips by eq. 20 itself. Heat maps as in Fig. 13: the frame they project
// onto (FILE.frame.json, at the start) and, at the end, each instrument's tips drawn on it
// (FILE.heatmap-forceps.png, FILE.heatmap-hook.png), named in the side file under "heat_maps".
// Pictures of the scene drawn offscreen at the start and at the end (FILE.view-start.png,
// FILE.view-end.png), named under "views"; a machine without OpenGL gets "views_problem" instead,
// and the recording goes on.
#include <map>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <vector>

#include "haptics/force_params.hpp"
#include "metrics/heat_map_frame.hpp"
#include "metrics/spatial_asymmetry.hpp"
#include "metrics/trainee_records.hpp"
#include "metrics/trajectory_recorder.hpp"
#include "runner/step_observer.hpp"
#include "session/surgical_session.hpp"

namespace imasim::cli {

// A step observer of the session runner: a row when one is due after each step.
class RunRecording final : public runner::StepObserver {
 public:
  // Opens FILE.csv and writes FILE.json, FILE.centerline.csv, FILE.heart.obj and
  // FILE.frame.json; throws
  // metrics::OutputError (also when one would overwrite one of `inputs`).
  RunRecording(const std::string& csv_path, std::span<const std::string> inputs,
               const haptics::ForceModelParams& forces, const nlohmann::ordered_json& run,
               const session::SurgicalSession& session, Real ima_radius,
               const std::map<std::string, double>& thresholds = {});

  // A row when one is due at the session's time (call at the start and after each step).
  void sample(const session::SurgicalSession& session);
  void after_step(const session::SurgicalSession& session, const runner::StepRecord&) override {
    sample(session);
  }
  using runner::StepObserver::finish;  // the run's end as an observer: nothing (the finish below)
  // Closes the CSV and rewrites the side file with `ending` (status, steps, rows) and the
  // scores; returns them: the SAI of each instrument's tips (eq. 20, R = 2 mm) and the trainee
  // metrics with their thresholds and pass or fail (metrics/trainee_metrics.hpp). Draws the two
  // heat maps (subtitled with their SAI) before it rewrites the side file.
  nlohmann::ordered_json finish(const nlohmann::ordered_json& ending,
                                const session::SurgicalSession& session);

  // After finish: the scores as the trainee records keep them (SAI per instrument, every
  // metric); the caller fills in who, when and what was run.
  metrics::SessionRecord scored_session() const;
  // After finish: adds `key` to the side file's "run" object and writes the file again.
  void add_to_side(const std::string& key, const nlohmann::ordered_json& value);

  std::size_t rows() const { return trajectory_.rows(); }
  const std::string& side_path() const { return side_path_; }

  // FILE.csv -> FILE.json and FILE.events.csv (a path without .csv gets the suffix added).
  static std::string side_path_of(const std::string& csv_path);
  static std::string events_path_of(const std::string& csv_path);
  static std::string centerline_path_of(const std::string& csv_path);
  static std::string heart_path_of(const std::string& csv_path);
  static std::string frame_path_of(const std::string& csv_path);
  // FILE.heatmap-TOOL.png
  static std::string heat_map_path_of(const std::string& csv_path, std::string_view tool);
  // FILE.view-WHEN.png
  static std::string view_path_of(const std::string& csv_path, std::string_view when);

 private:
  void write_side(const nlohmann::ordered_json& run);
  nlohmann::ordered_json draw_heat_maps(const nlohmann::ordered_json& sai);
  void draw_view(const session::SurgicalSession& session, std::string_view when);

  metrics::TrajectoryRecorder trajectory_;
  metrics::SideReference side_;
  metrics::HeatMapFrame frame_;
  std::string csv_path_;
  std::vector<metrics::TrajectorySample> rows_;  // every recorded row, for the scores
  Real ima_radius_ = 0;
  std::map<std::string, double> thresholds_;
  haptics::ForceModelParams forces_;
  std::string side_path_;
  std::vector<std::string> inputs_;
  nlohmann::ordered_json run_;
  nlohmann::ordered_json finished_run_;  // run_ with the ending and the scores
  nlohmann::ordered_json views_ = nlohmann::ordered_json::object();  // when -> PNG file
  std::string views_problem_;
  metrics::SessionRecord scored_;
};

}  // namespace imasim::cli
