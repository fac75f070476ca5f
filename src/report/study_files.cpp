#include "report/study_files.hpp"

#include <cmath>
#include <cstdio>

#include "metrics/output_file.hpp"
#include "report/study_html.hpp"

namespace imasim::report {

namespace {

using OrderedJson = nlohmann::ordered_json;

OrderedJson group_json(const metrics::GroupSummary& g) {
  return {{"n", g.n}, {"mean", g.mean}, {"sd", g.sd}};
}

OrderedJson test_json(const SaiComparison& c) {
  if (!c.test) return nullptr;
  const metrics::TwoGroupComparison& t = *c.test;
  return {{"a", c.groups[0].mode},      {"b", c.groups[1].mode},    {"t_welch", t.welch.t},
          {"df_welch", t.welch.df},     {"p_welch", t.welch.p},     {"t_student", t.student.t},
          {"df_student", t.student.df}, {"p_student", t.student.p}, {"cohen_d", t.cohen_d}};
}

OrderedJson trial_json(const TrialResult& t) {
  OrderedJson j;
  j["mode"] = t.mode;
  j["trial"] = t.trial;
  j["patient_seed"] = t.patient_seed;
  j["operator_seed"] = t.operator_seed ? OrderedJson(*t.operator_seed) : OrderedJson(nullptr);
  j["status"] = t.ok ? "ok" : "failed";
  j["reason"] = t.reason;
  j["wall_s"] = t.wall_s;
  j["files"] = t.files;
  OrderedJson sai = OrderedJson::object();
  for (const auto& [tool, v] : t.sai)
    sai[tool] = {{"sai", v.sai},
                 {"samples", v.samples},
                 {"mean_distance_m", v.mean_distance_m},
                 {"heart_side_fraction", v.heart_side_fraction}};
  j["sai"] = sai;
  OrderedJson metrics = OrderedJson::object();
  for (const MetricValue& m : t.metrics)
    metrics[m.name] = {{"value", m.value}, {"pass", m.pass}};
  j["metrics"] = metrics;
  j["heat_maps"] = t.heat_maps;
  return j;
}

// A CSV field with no comma, quote or line break (pandas reads the file with no options).
std::string plain(const std::string& text) {
  std::string out = text;
  for (char& c : out)
    if (c == ',' || c == '"' || c == '\n' || c == '\r') c = c == ',' ? ';' : ' ';
  return out;
}

std::string number(double v) {
  if (!std::isfinite(v)) return "";
  char out[32];
  std::snprintf(out, sizeof out, "%.10g", v);
  return out;
}

}  // namespace

nlohmann::ordered_json study_results_json(const StudyInfo& info,
                                          const std::vector<TrialResult>& trials,
                                          const StudySummary& summary) {
  OrderedJson j;
  j["format"] = "imasim study v1";
  OrderedJson study;
  study["program"] = info.program;
  study["date"] = info.date;
  study["status"] = info.status;
  study["scene"] = info.scene;
  study["modes"] = info.modes;
  study["trials_per_mode"] = info.trials_per_mode;
  study["seed"] = info.seed;
  study["operator"] = info.operator_kind;
  study["operator_description"] = info.operator_description;
  if (!info.script.empty()) study["script"] = info.script;
  study["seconds"] = info.seconds ? OrderedJson(*info.seconds) : OrderedJson(nullptr);
  study["jobs"] = info.jobs;
  study["trial_timeout_s"] = info.trial_timeout_s;
  j["study"] = study;
  j["headline"] = {{"score", "sai"}, {"instrument", kHeadlineInstrument}};
  OrderedJson sai = OrderedJson::object();
  for (const SaiComparison& c : summary.sai) {
    OrderedJson groups = OrderedJson::object();
    for (const SaiGroup& g : c.groups) {
      OrderedJson gj = group_json(g.summary);
      gj["values"] = g.values;
      gj["representative_trial"] = g.representative_trial;
      groups[g.mode] = gj;
    }
    sai[c.instrument] = {
        {"groups", groups}, {"test", test_json(c)}, {"test_problem", c.test_problem}};
  }
  j["sai"] = sai;
  OrderedJson metrics = OrderedJson::array();
  for (const MetricSummary& m : summary.metrics) {
    OrderedJson groups = OrderedJson::object();
    for (const MetricGroup& g : m.groups) {
      OrderedJson gj = group_json(g.summary);
      gj["passed"] = g.passed;
      gj["pass_rate"] = g.summary.n > 0 ? OrderedJson(double(g.passed) / double(g.summary.n))
                                        : OrderedJson(nullptr);
      groups[g.mode] = gj;
    }
    metrics.push_back({{"name", m.name},
                       {"unit", m.unit},
                       {"threshold", m.threshold},
                       {"better", m.higher_is_better ? "higher" : "lower"},
                       {"groups", groups}});
  }
  j["metrics"] = metrics;
  j["trials_ok"] = summary.trials_ok;
  j["trials_failed"] = summary.trials_failed;
  OrderedJson list = OrderedJson::array();
  for (const TrialResult& t : trials)
    list.push_back(trial_json(t));
  j["trials"] = list;
  j["files"] = {{"report", "report.html"}, {"trials_csv", "trials.csv"}, {"trials", "trials/"}};
  return j;
}

std::string trials_csv(const std::vector<TrialResult>& trials, const StudySummary& summary) {
  std::string out = "mode,trial,patient_seed,operator_seed,status,reason,wall_s";
  for (const char* tool : kInstruments)
    out += std::string(",sai_") + tool;
  for (const MetricSummary& m : summary.metrics)
    out += "," + m.name;
  out += '\n';
  for (const TrialResult& t : trials) {
    out += plain(t.mode) + "," + std::to_string(t.trial) + "," + std::to_string(t.patient_seed) +
           "," + (t.operator_seed ? std::to_string(*t.operator_seed) : "") + "," +
           (t.ok ? "ok" : "failed") + "," + plain(t.reason) + "," + number(t.wall_s);
    for (const char* tool : kInstruments) {
      out += ',';
      if (t.sai.contains(tool)) out += number(t.sai.at(tool).sai);
    }
    for (const MetricSummary& m : summary.metrics) {
      std::string cell;
      for (const MetricValue& v : t.metrics)
        if (v.name == m.name) cell = number(v.value);
      out += ',';
      out += cell;
    }
    out += '\n';
  }
  return out;
}

StudyFiles write_study_files(const std::string& dir, const StudyInfo& info,
                             const std::vector<TrialResult>& trials, const StudySummary& summary,
                             const std::vector<ReportImage>& images,
                             const std::vector<ReportTable>& tables) {
  StudyFiles files{dir + "/report.html", dir + "/results.json", dir + "/trials.csv"};
  auto write = [](const std::string& path, const char* what, const std::string& text) {
    metrics::OutputFile f(path, what);
    f.write(text);
    f.close();
  };
  write(files.results_json, "the study's results",
        study_results_json(info, trials, summary).dump(2) + "\n");
  write(files.trials_csv, "the study's trial table", trials_csv(trials, summary));
  write(files.report_html, "the study's report",
        study_report_html(info, trials, summary, images, tables));
  return files;
}

}  // namespace imasim::report
