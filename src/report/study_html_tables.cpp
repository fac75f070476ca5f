#include <cmath>
#include <cstdio>
#include <map>

#include "report/sai_chart.hpp"
#include "report/study_html_parts.hpp"
#include "report/text_format.hpp"

namespace imasim::report::html {

namespace {

std::string mode_heading(const std::string& mode, std::size_t index) {
  return "<span class=\"swatch\" style=\"background:" + mode_colour(mode, index) + "\"></span>" +
         html_escape(mode);
}

// A trial's SAI cell: the value, or why there is none.
std::string sai_cell(const TrialResult* t, const std::string& instrument) {
  if (t == nullptr) return "<td class=\"none\">not run</td>";
  if (!t->ok) return "<td class=\"failed\" title=\"" + html_escape(t->reason) + "\">failed</td>";
  if (!t->sai.contains(instrument)) return "<td class=\"none\">-</td>";
  return "<td>" + fixed(t->sai.at(instrument).sai, 3) + "</td>";
}

std::string group_cell(const SaiGroup& g) {
  if (g.values.empty()) return "<td class=\"none\">-</td>";
  // One value has no SD.
  if (g.values.size() < 2) return "<td>" + fixed(g.summary.mean, 3) + "</td>";
  return "<td>" + mean_sd(g.summary.mean, g.summary.sd, 3) + "</td>";
}

}  // namespace

const TrialResult* find_trial(const std::vector<TrialResult>& trials, const std::string& mode,
                              int number) {
  for (const TrialResult& t : trials)
    if (t.mode == mode && t.trial == number) return &t;
  return nullptr;
}

std::string mode_phrase(const std::string& mode) {
  if (mode == "dynamic") return "the beating heart";
  if (mode == "static") return "the static heart";
  return "mode " + mode;
}

std::string short_number(double v) {
  if (!std::isfinite(v)) return "-";
  char out[32];
  if (v == std::round(v) && std::abs(v) < 1e9)
    std::snprintf(out, sizeof out, "%.0f", v);
  else
    std::snprintf(out, sizeof out, "%.4g", v);
  return out;
}

std::string sai_table(const StudyInfo& info, const std::vector<TrialResult>& trials,
                      const StudySummary& summary) {
  // The headline instrument first, as the paper's Table 1; the forceps beside it.
  std::vector<const SaiComparison*> order = {&headline_sai(summary)};
  for (const SaiComparison& c : summary.sai)
    if (c.instrument != kHeadlineInstrument) order.push_back(&c);
  std::string h =
      "<table class=\"data sai\"><caption>Table 1. Spatial Asymmetry Index per trial "
      "(eq. 20, R = 2 mm). Trial k is the same virtual patient in every mode.</caption>"
      "<thead><tr><th rowspan=\"2\">Trial</th>";
  for (const SaiComparison* c : order)
    h += "<th colspan=\"" + std::to_string(info.modes.size()) + "\">" + html_escape(c->instrument) +
         (c->instrument == kHeadlineInstrument ? " (headline)" : "") + "</th>";
  h += "</tr><tr>";
  for (std::size_t k = 0; k < order.size(); ++k)
    for (std::size_t m = 0; m < info.modes.size(); ++m)
      h += "<th>" + mode_heading(info.modes[m], m) + "</th>";
  h += "</tr></thead><tbody>";
  for (int n = 1; n <= info.trials_per_mode; ++n) {
    h += "<tr><td>" + std::to_string(n) + "</td>";
    for (const SaiComparison* c : order)
      for (const std::string& mode : info.modes)
        h += sai_cell(find_trial(trials, mode, n), c->instrument);
    h += "</tr>";
  }
  h += "</tbody><tfoot><tr><th>Mean ± SD</th>";
  for (const SaiComparison* c : order)
    for (const SaiGroup& g : c->groups)
      h += group_cell(g);
  h += "</tr></tfoot></table>";
  return h;
}

std::string tests_table(const StudySummary& summary) {
  std::string h =
      "<table class=\"data\"><caption>Table 2. The groups compared (two-sided tests; Cohen's d "
      "is the difference of the means over the pooled SD).</caption><thead><tr><th>Instrument</th>"
      "<th>Welch's t</th><th>df</th><th>p</th><th>Student's t</th><th>df</th><th>p</th>"
      "<th>Cohen's d</th></tr></thead><tbody>";
  for (const SaiComparison& c : summary.sai) {
    h += "<tr><td>" + html_escape(c.instrument) + "</td>";
    if (!c.test) {
      h +=
          "<td colspan=\"7\" class=\"none\">no test: " + html_escape(c.test_problem) + "</td></tr>";
      continue;
    }
    const metrics::TwoGroupComparison& t = *c.test;
    h += "<td>" + fixed(t.welch.t, 2) + "</td><td>" + fixed(t.welch.df, 1) + "</td><td>" +
         html_escape(p_text(t.welch.p)) + "</td><td>" + fixed(t.student.t, 2) + "</td><td>" +
         fixed(t.student.df, 0) + "</td><td>" + html_escape(p_text(t.student.p)) + "</td><td>" +
         fixed(t.cohen_d, 2) + " (" + effect_size_words(t.cohen_d) + ")</td></tr>";
  }
  return h + "</tbody></table>";
}

std::string metrics_table(const StudySummary& summary) {
  if (summary.metrics.empty()) return "<p class=\"none\">No trial finished with metrics.</p>";
  std::string h =
      "<table class=\"data\"><caption>Table 3. Trainee metrics per group: mean ± SD "
      "over the finished trials and the share of trials at the pass mark."
      "</caption><thead><tr><th>Metric</th><th>Unit</th><th>Pass mark</th>";
  const std::vector<MetricGroup>& first = summary.metrics.front().groups;
  for (std::size_t m = 0; m < first.size(); ++m)
    h += "<th>" + mode_heading(first[m].mode, m) + "</th><th>passed</th>";
  h += "</tr></thead><tbody>";
  for (const MetricSummary& s : summary.metrics) {
    h += "<tr><td class=\"name\">" + html_escape(s.name) + "</td><td>" + html_escape(s.unit) +
         "</td><td>" + (s.higher_is_better ? "&ge; " : "&le; ") + short_number(s.threshold) +
         "</td>";
    for (const MetricGroup& g : s.groups) {
      if (g.summary.n == 0) {
        h += "<td class=\"none\">-</td><td class=\"none\">-</td>";
        continue;
      }
      const bool all = g.passed == g.summary.n;
      h += "<td>" + short_number(g.summary.mean) + " ± " + short_number(g.summary.sd) +
           "</td><td class=\"" + (all ? "pass" : "fail") + "\">" + std::to_string(g.passed) +
           " / " + std::to_string(g.summary.n) + "</td>";
    }
    h += "</tr>";
  }
  return h + "</tbody></table>";
}

std::string metrics_per_trial_table(const std::vector<TrialResult>& trials,
                                    const StudySummary& summary) {
  std::string h =
      "<div class=\"wide\"><table class=\"data compact\"><caption>Table 4. Every "
      "metric of every finished trial (values that miss the pass mark in red)."
      "</caption><thead><tr><th>Metric</th>";
  std::vector<const TrialResult*> done;
  for (const TrialResult& t : trials)
    if (t.ok) done.push_back(&t);
  for (const TrialResult* t : done)
    h += "<th>" + html_escape(t->mode) + " " + std::to_string(t->trial) + "</th>";
  h += "</tr></thead><tbody>";
  for (const MetricSummary& s : summary.metrics) {
    h += "<tr><td class=\"name\">" + html_escape(s.name) + "</td>";
    for (const TrialResult* t : done) {
      const MetricValue* found = nullptr;
      for (const MetricValue& v : t->metrics)
        if (v.name == s.name) found = &v;
      if (found == nullptr)
        h += "<td class=\"none\">-</td>";
      else
        h += std::string("<td") + (found->pass ? "" : " class=\"fail\"") + ">" +
             short_number(found->value) + "</td>";
    }
    h += "</tr>";
  }
  return h + "</tbody></table></div>";
}

std::string failed_trials(const std::vector<TrialResult>& trials) {
  std::string rows;
  for (const TrialResult& t : trials) {
    if (t.ok) continue;
    const std::string log = t.files.contains("log") ? t.files.at("log") : std::string();
    rows += "<tr><td>" + html_escape(t.mode) + "</td><td>" + std::to_string(t.trial) + "</td><td>" +
            html_escape(t.reason) + "</td><td class=\"path\">" + html_escape(log) + "</td></tr>";
  }
  if (rows.empty()) return "<p>None: every trial finished and was scored.</p>";
  return "<table class=\"data\"><thead><tr><th>Mode</th><th>Trial</th><th>Reason</th>"
         "<th>Its log</th></tr></thead><tbody>" +
         rows + "</tbody></table>";
}

}  // namespace imasim::report::html
