#pragma once
// The session's scores while it runs and its score card at the end (SPEC S6 and the trainee
// metrics): the 60 Hz rows kept in memory, the Spatial Asymmetry Index of each instrument so
// far (eq. 20), collisions between the instruments, and at the end the trainee metrics with
// their thresholds. Optionally the rows also go to a CSV file as they are taken (record).
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "haptics/force_params.hpp"
#include "metrics/spatial_asymmetry.hpp"
#include "metrics/trainee_metrics.hpp"
#include "metrics/trajectory_recorder.hpp"
#include "session/surgical_session.hpp"

namespace imasim::ui {

struct ScoreCard {
  double duration_s = 0;
  std::uint64_t strands_cut = 0, strands_total = 0, fascia_edges_cut = 0;
  std::uint64_t strands_torn = 0;  // pulled apart, not divided: rough handling
  std::uint64_t ima_injuries = 0, ima_injured_particles = 0;
  std::uint64_t heart_touches = 0, wall_touches = 0, ima_touches = 0;
  int instrument_collisions = 0;
  bool beating = true;
  bool sai_available = false;
  std::array<Real, 2> sai{};
  std::vector<metrics::TraineeMetric> metrics;  // empty when the scene cannot be scored
  std::size_t passed = 0;
};

class SessionScore {
 public:
  // `ima_radius`: the vessel's outer radius (unit: m). No SAI when the scene gives no side.
  SessionScore(const session::SurgicalSession& session, const haptics::ForceModelParams& forces,
               Real ima_radius);

  // After each step: a row when one is due (60 Hz); returns it when one was taken.
  const metrics::TrajectorySample* sample(const session::SurgicalSession& session);

  bool sai_available() const { return side_.has_value(); }
  Real sai(int tool) const;  // so far
  int instrument_collisions() const { return collisions_; }
  const std::vector<metrics::TrajectorySample>& rows() const { return rows_; }

  // Rows from now on also go to `csv_path` (metrics::OutputFile: throws metrics::OutputError).
  void start_recording(const std::string& csv_path, const std::string& scene_name, bool beating);
  void stop_recording();  // throws metrics::OutputError when the file cannot be completed
  bool recording() const { return recorder_ != nullptr; }
  std::size_t recorded_rows() const { return recorder_ ? recorder_->rows() : 0; }

  ScoreCard score_card(const session::SurgicalSession& session) const;

 private:
  haptics::ForceModelParams forces_;
  Real ima_radius_;
  std::optional<metrics::SideReference> side_;
  std::vector<metrics::TrajectorySample> rows_;
  double next_ = 0;  // simulated time of the next row
  std::array<double, 2> sai_sum_{0, 0};
  int collisions_ = 0;
  bool close_ = false;
  std::unique_ptr<metrics::TrajectoryRecorder> recorder_;
};

}  // namespace imasim::ui
