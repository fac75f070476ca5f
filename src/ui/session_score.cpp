#include "ui/session_score.hpp"

#include <cmath>

#include "console/trajectory_sample.hpp"

namespace imasim::ui {

namespace {

std::string side_path_of(const std::string& csv) {
  constexpr std::string_view ext = ".csv";
  const bool has_ext =
      csv.size() > ext.size() && csv.compare(csv.size() - ext.size(), ext.size(), ext) == 0;
  return (has_ext ? csv.substr(0, csv.size() - ext.size()) : csv) + ".json";
}

std::uint64_t count(const surgery::EventLog& log, surgery::EventKind kind, surgery::Tissue t) {
  std::uint64_t n = 0;
  for (const surgery::Event& e : log.events)
    n += e.kind == kind && e.tissue == t ? 1 : 0;
  return n;
}

}  // namespace

SessionScore::SessionScore(const session::SurgicalSession& s,
                           const haptics::ForceModelParams& forces, Real ima_radius)
    : forces_(forces), ima_radius_(ima_radius) {
  try {
    side_ =
        metrics::make_side_reference(s.scene.layout.ima_centerline, session::static_heart_mesh(s));
  } catch (const metrics::SaiError&) {
    side_.reset();  // a scene whose heart touches the vessel: scored without the SAI
  }
  rows_.reserve(std::size_t(60 * 600));  // ten minutes before the first reallocation
}

const metrics::TrajectorySample* SessionScore::sample(const session::SurgicalSession& s) {
  const double time = s.scene.patch.world.state.time;
  if (time < next_ - 1e-9) return nullptr;  // as metrics::TrajectoryRecorder::due
  rows_.push_back(console::trajectory_sample(s, forces_));
  const metrics::TrajectorySample& row = rows_.back();
  next_ = (std::floor(time * metrics::kRecordRateHz + 1e-6) + 1) / metrics::kRecordRateHz;
  if (side_) {
    for (std::size_t k = 0; k < 2; ++k) {
      const metrics::SideDistance d = metrics::side_distance(*side_, row.tools[k].tip);
      if (std::isfinite(d.distance))
        sai_sum_[k] += double(d.side) * double(d.distance) / double(metrics::kSaiRadius);
    }
  }
  // As trainee_metrics counts them: each approach of the tips within the distance once.
  const bool near =
      (row.tools[0].tip - row.tools[1].tip).norm() < metrics::MetricLimits{}.collision_distance;
  if (near && !close_) ++collisions_;
  close_ = near;
  if (recorder_) recorder_->record(row);
  return &row;
}

Real SessionScore::sai(int tool) const {
  if (!side_ || rows_.empty()) return 0;
  return Real(sai_sum_[std::size_t(tool)] / double(rows_.size()));
}

void SessionScore::start_recording(const std::string& csv_path, const std::string& scene_name,
                                   bool beating) {
  if (recorder_) return;
  nlohmann::ordered_json run;
  run["program"] = "imasim window";
  run["scene"] = scene_name;
  run["heart"] = beating ? "dynamic" : "static";
  run["input"] = "interactive";
  metrics::OutputFile side(side_path_of(csv_path), "the recording's side file");
  side.write(metrics::trajectory_side_file(run).dump(2) + "\n");
  side.close();
  recorder_ = std::make_unique<metrics::TrajectoryRecorder>(
      metrics::OutputFile(csv_path, "the trajectory file"));
}

void SessionScore::stop_recording() {
  if (!recorder_) return;
  std::unique_ptr<metrics::TrajectoryRecorder> r = std::move(recorder_);
  r->finish();
}

ScoreCard SessionScore::score_card(const session::SurgicalSession& s) const {
  ScoreCard c;
  const tissue::TissueWorld& w = s.scene.patch.world;
  c.duration_s = w.state.time;
  c.strands_cut = s.strands_cut;
  c.strands_torn = s.strands_torn;
  c.strands_total = w.strands[s.scene.patch.ima_fat].strand_count +
                    w.strands[s.scene.patch.fascia_fat].strand_count;
  c.fascia_edges_cut = s.fascia_edges_cut;
  c.ima_injuries = s.events.count(surgery::EventKind::injury);
  for (std::uint8_t injured : s.cautery.injured)
    c.ima_injured_particles += injured;
  c.heart_touches = count(s.events, surgery::EventKind::contact_begin, surgery::Tissue::heart);
  c.wall_touches = count(s.events, surgery::EventKind::contact_begin, surgery::Tissue::chest_wall);
  c.ima_touches = count(s.events, surgery::EventKind::contact_begin, surgery::Tissue::ima);
  c.instrument_collisions = collisions_;
  c.beating = s.scene.heart.playback.beating;
  c.sai_available = side_.has_value();
  if (side_) {
    c.sai = {sai(0), sai(1)};
    metrics::SessionTotals totals;
    totals.strands_total = c.strands_total;
    totals.strands_cut = c.strands_cut;
    totals.ima_radius = ima_radius_;
    c.metrics = metrics::trainee_metrics(rows_, s.events, *side_, totals);
    for (const metrics::TraineeMetric& m : c.metrics)
      c.passed += m.pass ? 1 : 0;
  }
  return c;
}

}  // namespace imasim::ui
