#include "run_recording.hpp"

#include "console/heat_map_frame_of.hpp"
#include "console/trajectory_sample.hpp"
#include "metrics/heat_map.hpp"
#include "metrics/trainee_metrics.hpp"
#include "score_report.hpp"
#include "session_view.hpp"

#include <cstdio>
#include <filesystem>

namespace imasim::cli {

namespace {

std::string stem_of(const std::string& csv) {
  constexpr std::string_view ext = ".csv";
  if (csv.size() > ext.size() && csv.compare(csv.size() - ext.size(), ext.size(), ext) == 0)
    return csv.substr(0, csv.size() - ext.size());
  return csv;
}

}  // namespace

std::string RunRecording::side_path_of(const std::string& csv) {
  return stem_of(csv) + ".json";
}

std::string RunRecording::events_path_of(const std::string& csv) {
  return stem_of(csv) + ".events.csv";
}

std::string RunRecording::centerline_path_of(const std::string& csv) {
  return stem_of(csv) + ".centerline.csv";
}

std::string RunRecording::heart_path_of(const std::string& csv) {
  return stem_of(csv) + ".heart.obj";
}

std::string RunRecording::frame_path_of(const std::string& csv) {
  return stem_of(csv) + ".frame.json";
}

std::string RunRecording::heat_map_path_of(const std::string& csv, std::string_view tool) {
  return stem_of(csv) + ".heatmap-" + std::string(tool) + ".png";
}

std::string RunRecording::view_path_of(const std::string& csv, std::string_view when) {
  return stem_of(csv) + ".view-" + std::string(when) + ".png";
}

namespace {

std::string number(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", v);  // exact: the scores read back the same
  return text;
}

void write_centerline(const std::string& path, std::span<const std::string> inputs,
                      const std::vector<Vec3>& centerline) {
  metrics::OutputFile f(path, "the centerline file", inputs);
  f.write("x,y,z\n");
  for (const Vec3& p : centerline)
    f.write(number(p.x()) + "," + number(p.y()) + "," + number(p.z()) + "\n");
  f.close();
}

void write_obj(const std::string& path, std::span<const std::string> inputs,
               const geometry::TriangleMesh& m) {
  metrics::OutputFile f(path, "the heart file", inputs);
  f.write("# imasim: the heart at its static phase, metres\n");
  for (const Vec3& v : m.vertices)
    f.write("v " + number(v.x()) + " " + number(v.y()) + " " + number(v.z()) + "\n");
  for (const geometry::Triangle& t : m.triangles)
    f.write("f " + std::to_string(t[0] + 1) + " " + std::to_string(t[1] + 1) + " " +
            std::to_string(t[2] + 1) + "\n");
  f.close();
}

}  // namespace

RunRecording::RunRecording(const std::string& csv_path, std::span<const std::string> inputs,
                           const haptics::ForceModelParams& forces,
                           const nlohmann::ordered_json& run, const session::SurgicalSession& s,
                           Real ima_radius, const std::map<std::string, double>& thresholds)
    : trajectory_(metrics::OutputFile(csv_path, "the trajectory file", inputs)),
      side_(metrics::make_side_reference(s.scene.layout.ima_centerline,
                                         session::static_heart_mesh(s))),
      frame_(console::heat_map_frame_of(s)),
      csv_path_(csv_path),
      ima_radius_(ima_radius),
      thresholds_(thresholds),
      forces_(forces),
      side_path_(side_path_of(csv_path)),
      inputs_(inputs.begin(), inputs.end()),
      run_(run) {
  inputs_.push_back(csv_path);
  run_["centerline_file"] = centerline_path_of(csv_path);
  run_["heart_file"] = heart_path_of(csv_path);
  run_["heat_maps"] = {{"frame", frame_path_of(csv_path)}};
  write_side(run_);
  write_centerline(centerline_path_of(csv_path), inputs_, side_.centerline);
  write_obj(heart_path_of(csv_path), inputs_, session::static_heart_mesh(s));
  metrics::write_heat_map_frame(frame_, frame_path_of(csv_path), inputs_);
  draw_view(s, "start");
}

void RunRecording::draw_view(const session::SurgicalSession& s, std::string_view when) {
  if (!views_problem_.empty()) return;  // no OpenGL here: said once
  const std::string path = view_path_of(csv_path_, when);
  for (const std::string& input : inputs_)
    if (std::filesystem::weakly_canonical(input) == std::filesystem::weakly_canonical(path)) {
      views_problem_ = "the picture " + path + " would overwrite an input";
      return;
    }
  try {
    draw_session_view(s, path);
    views_[std::string(when)] = path;
  } catch (const std::exception& e) {
    views_problem_ = e.what();  // the recording matters more than its pictures
  }
}

nlohmann::ordered_json RunRecording::draw_heat_maps(const nlohmann::ordered_json& sai) {
  nlohmann::ordered_json files;
  files["frame"] = frame_path_of(csv_path_);
  for (std::size_t k = 0; k < 2; ++k) {
    const std::string tool(metrics::kToolNames[k]);
    std::vector<Vec3> tips;
    tips.reserve(rows_.size());
    for (const metrics::TrajectorySample& r : rows_)
      tips.push_back(r.tools[k].tip);
    metrics::HeatMapStyle style;
    style.title = "Tool-tip density: " + tool;
    char subtitle[160];
    std::snprintf(subtitle, sizeof subtitle, "SAI = %.3f (R = %g mm), %s heart, %.1f s recorded",
                  sai[tool]["sai"].get<double>(), 1000 * double(metrics::kSaiRadius),
                  run_.value("heart", std::string("unknown")).c_str(),
                  rows_.empty() ? 0.0 : rows_.back().time - rows_.front().time);
    style.subtitle = subtitle;
    const std::string path = heat_map_path_of(csv_path_, tool);
    try {
      metrics::write_heat_map_png(frame_, tips, style, path, inputs_);
    } catch (const std::invalid_argument& e) {
      throw metrics::OutputError("cannot draw " + path + ": " + e.what());
    }
    files[tool] = path;
  }
  return files;
}

void RunRecording::write_side(const nlohmann::ordered_json& run) {
  nlohmann::ordered_json body = metrics::trajectory_side_file(run);
  body["trajectory_file"] = trajectory_.path();
  metrics::OutputFile side(side_path_, "the trajectory's side file", inputs_);
  side.write(body.dump(2) + '\n');
  side.close();
}

void RunRecording::sample(const session::SurgicalSession& s) {
  if (!trajectory_.due(s.scene.patch.world.state.time)) return;
  const metrics::TrajectorySample row = console::trajectory_sample(s, forces_);
  trajectory_.record(row);
  rows_.push_back(row);
}

nlohmann::ordered_json RunRecording::finish(const nlohmann::ordered_json& ending,
                                            const session::SurgicalSession& s) {
  trajectory_.finish();
  nlohmann::ordered_json scores;
  nlohmann::ordered_json sai;
  sai["radius_m"] = metrics::kSaiRadius;
  scored_ = {};
  scored_.sai_radius = double(metrics::kSaiRadius);
  for (std::size_t k = 0; k < 2; ++k) {
    std::vector<Vec3> tips;
    tips.reserve(rows_.size());
    for (const metrics::TrajectorySample& r : rows_)
      tips.push_back(r.tools[k].tip);
    const metrics::SaiResult result = metrics::spatial_asymmetry(side_, tips);
    sai[std::string(metrics::kToolNames[k])] = sai_report(result);
    scored_.sai.push_back({std::string(metrics::kToolNames[k]), result});
  }
  scores["sai"] = sai;
  metrics::SessionTotals totals;
  const tissue::TissueWorld& w = s.scene.patch.world;
  totals.strands_total = w.strands[s.scene.patch.ima_fat].strand_count +
                         w.strands[s.scene.patch.fascia_fat].strand_count;
  totals.strands_cut = s.strands_cut;
  totals.ima_radius = ima_radius_;
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  std::size_t passed = 0;
  for (const metrics::TraineeMetric& m :
       metrics::trainee_metrics(rows_, s.events, side_, totals, {}, thresholds_)) {
    list.push_back(metric_report(m));
    passed += m.pass ? 1 : 0;
    scored_.metrics.push_back(m);
  }
  scores["metrics"] = list;
  scores["metrics_passed"] = passed;
  scores["metrics_total"] = list.size();
  nlohmann::ordered_json run = run_;
  for (auto it = ending.begin(); it != ending.end(); ++it)
    run[it.key()] = it.value();
  run["rows"] = trajectory_.rows();
  run["scores"] = scores;
  run["heat_maps"] = draw_heat_maps(sai);
  draw_view(s, "end");
  run["views"] = views_;
  if (!views_problem_.empty()) run["views_problem"] = views_problem_;
  write_side(run);
  finished_run_ = run;
  return scores;
}

metrics::SessionRecord RunRecording::scored_session() const {
  return scored_;
}

void RunRecording::add_to_side(const std::string& key, const nlohmann::ordered_json& value) {
  finished_run_[key] = value;
  write_side(finished_run_);
}

}  // namespace imasim::cli
