#include "study_records.hpp"

#include "cli_checks.hpp"
#include "metrics/line_plot.hpp"
#include "metrics/records_path.hpp"
#include "metrics/trainee_progress.hpp"
#include "metrics/trainee_records.hpp"
#include "report/text_format.hpp"

namespace imasim::cli {

void add_study_records_options(CLI::App& cmd, OperatorChoice& op) {
  cmd.add_option("--trainee", op.trainee,
                 "The name the trials are recorded under in the trainee records")
      ->capture_default_str()
      ->check(trainee_name());
  CLI::Option* db = cmd.add_option("--db", op.db,
                                   "The trainee records (SQLite) each scored trial is appended "
                                   "to; default: the user's (see `imasim history`)")
                        ->check(non_empty());
  cmd.add_flag("--no-db", op.no_db, "Append no trainee record")->excludes(db);
}

namespace {

// One series per heart mode: a score's value at each of the trainee's session numbers.
metrics::LinePlot history_plot(const std::vector<metrics::SessionRecord>& sessions,
                               const std::string& trainee) {
  metrics::LinePlot plot;
  plot.title = "History of '" + trainee + "': the hook's SAI per session";
  plot.x_label = "session";
  plot.y_label = "SAI (eq. 20, R = 2 mm)";
  for (const metrics::HeartMode mode :
       {metrics::HeartMode::dynamic, metrics::HeartMode::static_heart}) {
    metrics::PlotSeries series;
    series.name = std::string(metrics::to_string(mode)) + " heart";
    series.style = metrics::SeriesStyle::markers;
    for (std::size_t i = 0; i < sessions.size(); ++i) {
      const metrics::SaiResult* sai = metrics::find_sai(sessions[i], "hook");
      if (sessions[i].heart != mode || !sai) continue;
      series.x.push_back(double(i + 1));
      series.y.push_back(double(sai->sai));
    }
    if (!series.x.empty()) plot.series.push_back(series);
  }
  return plot;
}

metrics::LinePlot passed_plot(const std::vector<metrics::SessionRecord>& sessions,
                              const std::string& trainee) {
  metrics::LinePlot plot;
  plot.title = "History of '" + trainee + "': trainee metrics passed per session";
  plot.x_label = "session";
  plot.y_label = "share of metrics passed";
  plot.y_from_zero = true;
  metrics::PlotSeries series;
  series.name = "passed / all";
  for (std::size_t i = 0; i < sessions.size(); ++i) {
    const metrics::PassCount c = metrics::pass_count(sessions[i]);
    if (c.total == 0) continue;
    series.x.push_back(double(i + 1));
    series.y.push_back(double(c.passed) / double(c.total));
  }
  if (!series.x.empty()) plot.series.push_back(series);
  return plot;
}

// The sessions as a table, at most the latest `kMaxRows`.
constexpr std::size_t kMaxRows = 40;

report::ReportTable history_table(const std::vector<metrics::SessionRecord>& sessions,
                                  const std::string& trainee, const std::string& path) {
  report::ReportTable table;
  const std::size_t first = sessions.size() > kMaxRows ? sessions.size() - kMaxRows : 0;
  table.caption = "Table 5. The sessions of '" + trainee + "' in the trainee records (" + path +
                  ")" + (first > 0 ? ", the latest " + std::to_string(kMaxRows) : "") + ".";
  table.header = {"session",  "date (UTC)",  "heart",         "status",
                  "SAI hook", "SAI forceps", "metrics passed"};
  const auto sai_text = [](const metrics::SessionRecord& r, const char* tool) {
    const metrics::SaiResult* sai = metrics::find_sai(r, tool);
    return sai ? report::fixed(double(sai->sai), 3) : std::string("-");
  };
  for (std::size_t i = first; i < sessions.size(); ++i) {
    const metrics::SessionRecord& r = sessions[i];
    const metrics::PassCount c = metrics::pass_count(r);
    table.rows.push_back({std::to_string(i + 1), r.date_utc, metrics::to_string(r.heart), r.status,
                          sai_text(r, "hook"), sai_text(r, "forceps"),
                          std::to_string(c.passed) + " of " + std::to_string(c.total)});
  }
  return table;
}

}  // namespace

StudyHistory study_history(const OperatorChoice& op, const std::string& dir, std::string& problem) {
  StudyHistory history;
  std::vector<report::ReportImage>& figures = history.images;
  if (op.no_db) return history;
  try {
    const std::string path = op.db.empty() ? metrics::default_records_path() : op.db;
    const metrics::TraineeRecords records(path, metrics::TraineeRecords::Access::read_only);
    const std::vector<metrics::SessionRecord> sessions = records.sessions(op.trainee);
    if (sessions.empty()) return history;
    history.tables.push_back(history_table(sessions, op.trainee, path));
    const std::string n = std::to_string(sessions.size());
    const metrics::LinePlot sai = history_plot(sessions, op.trainee);
    if (!sai.series.empty()) {
      const std::string png = dir + "/history-sai.png";
      metrics::write_line_plot_png(sai, png);
      figures.push_back({"Trainee history (" + path + "): the hook's SAI in each of '" +
                             op.trainee + "''s " + n + " recorded sessions, this study's included",
                         png});
    }
    const metrics::LinePlot passed = passed_plot(sessions, op.trainee);
    if (!passed.series.empty()) {
      const std::string png = dir + "/history-passed.png";
      metrics::write_line_plot_png(passed, png);
      figures.push_back({"Trainee history: the share of trainee metrics passed in each of '" +
                             op.trainee + "''s " + n + " sessions",
                         png});
    }
  } catch (const std::exception& e) {
    problem = e.what();
  }
  return history;
}

}  // namespace imasim::cli
