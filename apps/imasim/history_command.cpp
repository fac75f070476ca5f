#include "history_command.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>

#include "cli_checks.hpp"
#include "history_report.hpp"
#include "math/edit_distance.hpp"
#include "math/printable.hpp"
#include "metrics/records_path.hpp"
#include "metrics/trainee_metrics.hpp"
#include "metrics/trainee_records.hpp"

namespace imasim::cli {

namespace {

std::string nearest(const std::string& name, const std::vector<std::string>& names) {
  std::string best = names.front();
  for (const std::string& n : names)
    if (edit_distance(name, n) < edit_distance(name, best)) best = n;
  return best;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names)
    out += (out.empty() ? "" : ", ") + n;
  return out;
}

}  // namespace

std::shared_ptr<HistoryOptions> add_history_command(CLI::App& app) {
  auto opt = std::make_shared<HistoryOptions>();
  CLI::App* cmd = app.add_subcommand("history", "Trainees' progress over their recorded sessions");
  cmd->add_option("--trainee", opt->trainee, "Only this trainee's sessions")->check(trainee_name());
  cmd->add_option("--db", opt->db_file,
                  "The trainee records (SQLite); default: $XDG_DATA_HOME/imasim/trainees.sqlite, "
                  "else ~/.local/share/imasim/trainees.sqlite")
      ->check(non_empty());
  cmd->add_option("--metric", opt->metric,
                  "Also this metric's value, threshold and pass over the sessions")
      ->check(non_empty());
  cmd->add_flag("--json", opt->json, "Print one JSON object on stdout (docs/scoring.md)");
  return opt;
}

int run_history_command(const HistoryOptions& o) {
  std::string path;
  try {
    path = !o.db_file.empty() ? o.db_file : metrics::default_records_path();
  } catch (const metrics::RecordsError& e) {
    std::cerr << "imasim history: " << e.what() << '\n';
    return 2;
  }
  if (std::error_code ec; !std::filesystem::exists(path, ec)) {
    std::cerr << "imasim history: no trainee records at " << path
              << " (a recorded run, `imasim run --record FILE.csv`, appends there; --db names "
                 "another database)\n";
    return 2;
  }
  if (!o.metric.empty()) {
    const std::vector<std::string> names = metrics::trainee_metric_names();
    if (std::find(names.begin(), names.end(), o.metric) == names.end()) {
      std::cerr << "imasim history: --metric '" << printable(o.metric, 80)
                << "' is no metric; did you mean '" << nearest(o.metric, names)
                << "'? (metrics: " << joined(names) << ")\n";
      return 2;
    }
  }
  nlohmann::ordered_json report;
  try {
    const metrics::TraineeRecords records(path, metrics::TraineeRecords::Access::read_only);
    std::vector<std::string> trainees = records.trainees();
    if (!o.trainee.empty()) {
      if (std::find(trainees.begin(), trainees.end(), o.trainee) == trainees.end()) {
        std::cerr << "imasim history: no sessions of trainee '" << printable(o.trainee, 80)
                  << "' in " << path << " (trainees: "
                  << (trainees.empty() ? std::string("none yet") : joined(trainees)) << ")\n";
        return 2;
      }
      trainees = {o.trainee};
    }
    report = history_report(records, trainees, o.metric);
  } catch (const metrics::RecordsError& e) {
    std::cerr << "imasim history: " << e.what() << '\n';
    return 2;
  }
  if (o.json)
    std::cout << report.dump() << '\n';
  else
    std::cout << history_text(report);
  std::cout.flush();
  return std::cout ? 0 : 4;
}

}  // namespace imasim::cli
