#include "run_recording.hpp"

#include "console/trajectory_sample.hpp"

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

RunRecording::RunRecording(const std::string& csv_path, std::span<const std::string> inputs,
                           const haptics::ForceModelParams& forces,
                           const nlohmann::ordered_json& run)
    : trajectory_(metrics::OutputFile(csv_path, "the trajectory file", inputs)),
      forces_(forces),
      side_path_(side_path_of(csv_path)),
      inputs_(inputs.begin(), inputs.end()),
      run_(run) {
  inputs_.push_back(csv_path);
  write_side(run_);
}

void RunRecording::write_side(const nlohmann::ordered_json& run) {
  nlohmann::ordered_json body = metrics::trajectory_side_file(run);
  body["trajectory_file"] = trajectory_.path();
  metrics::OutputFile side(side_path_, "the trajectory's side file", inputs_);
  side.write(body.dump(2) + '\n');
  side.close();
}

void RunRecording::sample(const session::SurgicalSession& s) {
  if (trajectory_.due(s.scene.patch.world.state.time))
    trajectory_.record(console::trajectory_sample(s, forces_));
}

void RunRecording::finish(const nlohmann::ordered_json& ending) {
  trajectory_.finish();
  nlohmann::ordered_json run = run_;
  for (auto it = ending.begin(); it != ending.end(); ++it)
    run[it.key()] = it.value();
  run["rows"] = trajectory_.rows();
  write_side(run);
}

}  // namespace imasim::cli
