#include "history_report.hpp"

#include <cstdio>

#include "metrics/trainee_progress.hpp"
#include "score_report.hpp"
#include "text_table.hpp"

namespace imasim::cli {

namespace {

nlohmann::ordered_json optional_number(const std::optional<double>& v) {
  return v ? nlohmann::ordered_json(*v) : nlohmann::ordered_json(nullptr);
}

nlohmann::ordered_json session_report(const metrics::SessionRecord& s, std::size_t number) {
  nlohmann::ordered_json j;
  j["number"] = number;
  j["id"] = s.id;
  j["date_utc"] = s.date_utc;
  j["scene"] = s.scene;
  j["heart"] = metrics::to_string(s.heart);
  j["patient_seed"] = s.patient_seed;
  j["operator"] = metrics::to_string(s.operator_kind);
  j["input"] = s.input;
  j["status"] = s.status;
  j["recording"] = s.recording;
  nlohmann::ordered_json sai;
  sai["radius_m"] = s.sai_radius;
  for (const metrics::InstrumentSai& i : s.sai)
    sai[i.instrument] = sai_report(i.result);
  j["sai"] = sai;
  const metrics::PassCount passed = metrics::pass_count(s);
  j["metrics_passed"] = passed.passed;
  j["metrics_total"] = passed.total;
  const metrics::TraineeMetric* time = metrics::find_metric(s, "time_to_complete_s");
  j["time_to_complete_s"] = optional_number(time ? std::optional(time->value) : std::nullopt);
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const metrics::TraineeMetric& m : s.metrics)
    list.push_back(metric_report(m));
  j["metrics"] = list;
  return j;
}

nlohmann::ordered_json progress_report(const metrics::TraineeProgress& p) {
  nlohmann::ordered_json j;
  j["sessions"] = p.sessions;
  j["first_passed"] = p.first.passed;
  j["first_total"] = p.first.total;
  j["first_passed_share"] = p.first.share();
  j["latest_passed"] = p.latest.passed;
  j["latest_total"] = p.latest.total;
  j["latest_passed_share"] = p.latest.share();
  j["passed_share_trend_per_session"] = p.passed_share_trend;
  j["first_time_to_complete_s"] = optional_number(p.first_time_to_complete_s);
  j["latest_time_to_complete_s"] = optional_number(p.latest_time_to_complete_s);
  return j;
}

nlohmann::ordered_json series_report(const metrics::MetricHistory& h) {
  nlohmann::ordered_json j;
  j["metric"] = h.metric;
  j["unit"] = h.unit;
  j["better"] = h.higher_is_better ? "higher" : "lower";
  nlohmann::ordered_json points = nlohmann::ordered_json::array();
  for (const metrics::HistoryPoint& p : h.points)
    points.push_back({{"number", p.session_number},
                      {"session_id", p.session_id},
                      {"date_utc", p.date_utc},
                      {"value", p.value},
                      {"threshold", p.threshold},
                      {"pass", p.pass}});
  j["points"] = points;
  return j;
}

std::string formatted(const char* format, double v) {
  char text[64];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

// A number of the report, or "-" for null (a metric the session did not have).
std::string cell(const nlohmann::ordered_json& v, const char* format) {
  return v.is_number() ? formatted(format, v.get<double>()) : std::string("-");
}

std::string percent(double share) {
  return formatted("%.0f %%", 100 * share);
}

std::string sessions_table(const nlohmann::ordered_json& sessions) {
  TextTable t;
  t.header = {"#",        "date",   "scene",    "heart", "SAI forceps",
              "SAI hook", "passed", "time (s)", "status"};
  t.right_aligned = {true, false, false, false, true, true, true, true, false};
  for (const auto& s : sessions) {
    const auto sai_of = [&s](const char* tool) {
      return s["sai"].contains(tool) ? cell(s["sai"][tool]["sai"], "%.3f") : std::string("-");
    };
    t.rows.push_back({std::to_string(s["number"].get<std::size_t>()),
                      s["date_utc"].get<std::string>(), s["scene"].get<std::string>(),
                      s["heart"].get<std::string>(), sai_of("forceps"), sai_of("hook"),
                      std::to_string(s["metrics_passed"].get<std::size_t>()) + "/" +
                          std::to_string(s["metrics_total"].get<std::size_t>()),
                      cell(s["time_to_complete_s"], "%.1f"), s["status"].get<std::string>()});
  }
  return format_table(t);
}

std::string progress_line(const nlohmann::ordered_json& p) {
  const auto count = [&p](const std::string& which) {
    return std::to_string(p[which + "_passed"].get<std::size_t>()) + "/" +
           std::to_string(p[which + "_total"].get<std::size_t>()) + " (" +
           percent(p[which + "_passed_share"].get<double>()) + ")";
  };
  const std::size_t n = p["sessions"].get<std::size_t>();
  if (n < 2)
    return "  progress: one session, " + count("first") + " metrics passed; no trend yet\n";
  std::string line = "  progress: metrics passed " + count("first") + " in session 1, " +
                     count("latest") + " in session " + std::to_string(n) + "; trend " +
                     formatted("%+.1f", 100 * p["passed_share_trend_per_session"].get<double>()) +
                     " points a session";
  if (p["first_time_to_complete_s"].is_number() && p["latest_time_to_complete_s"].is_number())
    line += "; time to complete " + cell(p["first_time_to_complete_s"], "%.1f") + " s -> " +
            cell(p["latest_time_to_complete_s"], "%.1f") + " s";
  return line + '\n';
}

std::string series_text(const nlohmann::ordered_json& series) {
  std::string out = "  " + series["metric"].get<std::string>() + " (unit " +
                    series["unit"].get<std::string>() + ", " + series["better"].get<std::string>() +
                    " is better):\n";
  if (series["points"].empty()) return out + "    no session has it\n";
  TextTable t;
  t.header = {"#", "date", "value", "threshold", "pass"};
  t.right_aligned = {true, false, true, true, false};
  for (const auto& p : series["points"])
    t.rows.push_back({std::to_string(p["number"].get<std::int64_t>()),
                      p["date_utc"].get<std::string>(), cell(p["value"], "%.6g"),
                      cell(p["threshold"], "%.6g"), p["pass"].get<bool>() ? "yes" : "no"});
  return out + format_table(t, "    ");
}

}  // namespace

nlohmann::ordered_json history_report(const metrics::TraineeRecords& records,
                                      const std::vector<std::string>& trainees,
                                      const std::string& metric) {
  nlohmann::ordered_json out;
  out["database"] = records.path();
  if (!metric.empty()) out["metric"] = metric;
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const std::string& name : trainees) {
    const std::vector<metrics::SessionRecord> sessions = records.sessions(name);
    nlohmann::ordered_json t;
    t["trainee"] = name;
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < sessions.size(); ++k)
      rows.push_back(session_report(sessions[k], k + 1));
    t["sessions"] = rows;
    t["progress"] = progress_report(metrics::trainee_progress(sessions));
    if (!metric.empty()) t["series"] = series_report(records.metric_history(name, metric));
    list.push_back(t);
  }
  out["trainees"] = list;
  return out;
}

std::string history_text(const nlohmann::ordered_json& report) {
  std::string out = "trainee records: " + report["database"].get<std::string>() + '\n';
  if (report["trainees"].empty()) return out + "no sessions recorded yet\n";
  for (const auto& t : report["trainees"]) {
    const std::size_t n = t["sessions"].size();
    out += '\n' + t["trainee"].get<std::string>() + ": " + std::to_string(n) +
           (n == 1 ? " session\n" : " sessions\n");
    out += sessions_table(t["sessions"]);
    out += progress_line(t["progress"]);
    if (t.contains("series")) out += series_text(t["series"]);
  }
  return out;
}

}  // namespace imasim::cli
