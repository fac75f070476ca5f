#include "report/study_html.hpp"

#include "report/sai_chart.hpp"
#include "report/study_html_parts.hpp"
#include "report/text_format.hpp"

namespace imasim::report {

namespace {

using html::mode_phrase;

constexpr const char* kStyle = R"CSS(
:root { --ink:#1d2733; --muted:#5b6673; --line:#d8dde3; --soft:#f4f6f8; --accent:#0f4c81; }
* { box-sizing: border-box; }
body { margin: 0; color: var(--ink); background: #fff;
  font: 15px/1.5 "DejaVu Sans", "Helvetica Neue", Arial, sans-serif; }
header { background: var(--accent); color: #fff; padding: 28px 48px 22px; }
header h1 { margin: 0 0 4px; font-size: 26px; font-weight: 600; }
header p { margin: 0; opacity: .85; }
main { max-width: 1180px; margin: 0 auto; padding: 8px 48px 40px; }
h2 { font-size: 20px; margin: 34px 0 10px; padding-bottom: 6px; border-bottom: 2px solid var(--line); }
h3 { font-size: 16px; margin: 20px 0 6px; }
.facts { border-collapse: collapse; }
.facts th { text-align: left; color: var(--muted); font-weight: normal; padding: 3px 24px 3px 0;
  vertical-align: top; white-space: nowrap; }
.facts td { padding: 3px 0; }
.note { margin: 16px 0; padding: 12px 16px; background: #fff8e6; border-left: 4px solid #e0a100; }
.cards { display: flex; gap: 16px; flex-wrap: wrap; margin: 12px 0; }
.card { flex: 1 1 220px; border: 1px solid var(--line); border-radius: 6px; padding: 14px 18px;
  border-top: 5px solid var(--c); }
.card .label { color: var(--muted); font-size: 13px; }
.card .value { font-size: 28px; font-weight: 600; }
.card .n { color: var(--muted); font-size: 13px; }
.result { display: flex; gap: 24px; flex-wrap: wrap; align-items: flex-start; }
.result .words { flex: 1 1 380px; }
table.data { border-collapse: collapse; margin: 12px 0 6px; font-variant-numeric: tabular-nums; }
table.data caption { caption-side: top; text-align: left; color: var(--muted); font-size: 13px;
  padding-bottom: 6px; }
table.data th, table.data td { border-bottom: 1px solid var(--line); padding: 5px 14px;
  text-align: right; }
table.data th { background: var(--soft); font-weight: 600; }
table.data thead th { text-align: center; }
table.data td:first-child, table.data th:first-child, table.data td.name, table.data td.path {
  text-align: left; }
table.data tfoot th, table.data tfoot td { border-top: 2px solid var(--ink); font-weight: 600; }
table.compact th, table.compact td { padding: 3px 8px; font-size: 13px; }
td.failed, td.fail { color: #b3261e; }
td.pass { color: #1e7b34; }
td.none, p.none { color: var(--muted); }
td.path { font-family: "DejaVu Sans Mono", monospace; font-size: 12px; }
.swatch { display: inline-block; width: 10px; height: 10px; border-radius: 2px; margin-right: 6px; }
.wide { overflow-x: auto; }
.figures { display: flex; gap: 18px; flex-wrap: wrap; }
figure { margin: 8px 0; border: 1px solid var(--line); border-radius: 6px; padding: 10px;
  background: #fff; }
figure img { display: block; max-width: 520px; height: auto; }
figcaption { color: var(--muted); font-size: 13px; margin-top: 6px; }
figure.missing p { color: #b3261e; max-width: 480px; }
footer { color: var(--muted); font-size: 13px; border-top: 1px solid var(--line);
  padding: 14px 48px; }
code { font-family: "DejaVu Sans Mono", monospace; font-size: 13px; }
)CSS";

// Marks the page ready on the window's load event, when every image has loaded or failed; an
// image with no decoded size is broken, a console error. Not img.decode(): its promise settles on
// the decoder thread, outside headless Chromium's virtual time, so a DOM dump could precede it.
constexpr const char* kReadyScript = R"JS(
function imasimMarkReady() {
  var broken = Array.from(document.images).filter(function (i) {
    return !i.complete || i.naturalWidth === 0;
  });
  document.body.dataset.ready = broken.length === 0 ? "yes" : "image-error";
  if (broken.length !== 0) console.error(broken.length + " image(s) did not load");
}
if (document.readyState === "complete") imasimMarkReady();
else window.addEventListener("load", imasimMarkReady);
)JS";

std::string fact(const std::string& name, const std::string& value) {
  return "<tr><th>" + name + "</th><td>" + value + "</td></tr>";
}

std::string join(const std::vector<std::string>& words) {
  std::string out;
  for (const std::string& w : words)
    out += (out.empty() ? "" : ", ") + w;
  return out;
}

std::string what_was_run(const StudyInfo& info, const std::vector<TrialResult>& trials) {
  std::string seeds;
  for (const TrialResult& t : trials)
    if (t.mode == info.modes.front())
      seeds += (seeds.empty() ? "" : ", ") + std::to_string(t.patient_seed);
  std::string h = "<table class=\"facts\">";
  h += fact("Program", html_escape(info.program));
  h += fact("Date", html_escape(info.date));
  h += fact("Scene", html_escape(info.scene));
  h += fact("Modes", html_escape(join(info.modes)));
  h += fact("Trials", std::to_string(info.trials_per_mode) + " per mode, " +
                          std::to_string(trials.size()) + " in all, " + std::to_string(info.jobs) +
                          " at a time");
  h += fact("Study seed", std::to_string(info.seed));
  h += fact("Patient seeds", html_escape(seeds) + " (trial 1, 2, ...; the same in every mode)");
  h += fact("Operator", html_escape(info.operator_description));
  if (info.seconds) h += fact("Simulated time", fixed(*info.seconds, 2) + " s a trial");
  if (info.trial_timeout_s > 0)
    h += fact("Time limit", fixed(info.trial_timeout_s, 0) + " s of wall-clock time a trial");
  if (info.status != "complete") h += fact("Status", html_escape(info.status));
  return h + "</table>";
}

std::string operator_note(const StudyInfo& info) {
  std::string h = "<div class=\"note\"><strong>About the operator.</strong> ";
  if (info.operator_kind == "autopilot")
    h += "The trials were performed by imasim's scripted operator, a test operator that drives "
         "the instruments through the console's device interface. It is not a model of surgeons: "
         "its behaviour near the heart (a keep-out margin that grows with the heart's motion) is "
         "a stated rule, so the groups differ for that stated reason, not because of human "
         "perception or skill.";
  else
    h += "Every trial played the same input script through the console's device interface: a "
         "fixed, scripted input, not a surgeon and not a model of one. The groups differ only by "
         "the heart's motion and the virtual patient.";
  return h + "</div>";
}

std::string card(const SaiGroup& g, std::size_t index) {
  const std::string value = g.values.empty()      ? std::string("-")
                            : g.values.size() < 2 ? fixed(g.summary.mean, 3)
                                                  : mean_sd(g.summary.mean, g.summary.sd, 3);
  return "<div class=\"card\" style=\"--c:" + mode_colour(g.mode, index) +
         "\"><div class=\"label\">" + html_escape(g.mode) + ": " +
         html_escape(mode_phrase(g.mode)) + "</div><div class=\"value\">" + value +
         "</div><div class=\"n\">mean ± SD of the hook's SAI, n = " +
         std::to_string(g.values.size()) + " trials</div></div>";
}

std::string result_words(const SaiComparison& c) {
  std::string h =
      "<p>The headline measure is the Spatial Asymmetry Index (eq. 20 of the paper, "
      "R = 2 mm) of the <strong>hook</strong>, the dissecting instrument: positive "
      "when the hook works on the side of the artery away from the heart, negative "
      "toward it, in units of R.</p>";
  if (!c.test) return h + "<p>No test: " + html_escape(c.test_problem) + ".</p>";
  const metrics::TwoGroupComparison& t = *c.test;
  const SaiGroup &a = c.groups[0], &b = c.groups[1];
  const bool significant = t.welch.p < 0.05;
  h += "<p>With " + html_escape(mode_phrase(a.mode)) + " the hook's SAI was " +
       mean_sd(a.summary.mean, a.summary.sd, 3) +
       " (mean ± SD, n = " + std::to_string(a.summary.n) + "); with " +
       html_escape(mode_phrase(b.mode)) + " " + mean_sd(b.summary.mean, b.summary.sd, 3) +
       " (n = " + std::to_string(b.summary.n) + "). The difference of " +
       fixed(a.summary.mean - b.summary.mean, 3) + " is " +
       (significant ? "statistically significant" : "not statistically significant") +
       " at the 5 % level: Welch's t-test, which does not assume equal variances, gives t = " +
       fixed(t.welch.t, 2) + " with " + fixed(t.welch.df, 1) + " degrees of freedom, " +
       html_escape(p_text(t.welch.p)) +
       " (two-sided); Student's t-test with pooled variance gives t = " + fixed(t.student.t, 2) +
       ", df = " + fixed(t.student.df, 0) + ", " + html_escape(p_text(t.student.p)) +
       ". Cohen's d is " + fixed(t.cohen_d, 2) + ", a " + effect_size_words(t.cohen_d) +
       " effect.</p>";
  return h;
}

// A table of text cells, every cell escaped.
std::string text_table_html(const ReportTable& table) {
  std::string h = "<table><caption>" + html_escape(table.caption) + "</caption><thead><tr>";
  for (const std::string& cell : table.header)
    h += "<th>" + html_escape(cell) + "</th>";
  h += "</tr></thead><tbody>";
  for (const std::vector<std::string>& row : table.rows) {
    h += "<tr>";
    for (const std::string& cell : row)
      h += "<td>" + html_escape(cell) + "</td>";
    h += "</tr>";
  }
  return h + "</tbody></table>";
}

}  // namespace

std::string study_report_html(const StudyInfo& info, const std::vector<TrialResult>& trials,
                              const StudySummary& summary, const std::vector<ReportImage>& images,
                              const std::vector<ReportTable>& tables) {
  const SaiComparison& headline = headline_sai(summary);
  std::string title = "IMA harvesting study";
  if (info.modes.size() == 2) title += ": " + info.modes[0] + " versus " + info.modes[1] + " heart";
  std::string h =
      "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">"
      "<title>" +
      html_escape(title) + "</title><style>" + kStyle + "</style></head><body>";
  h += "<header><h1>" + html_escape(title) +
       "</h1><p>Robotic internal mammary artery "
       "harvesting in imasim &middot; " +
       html_escape(info.program) + " &middot; " + html_escape(info.date) + "</p></header><main>";
  h += "<section id=\"run\"><h2>What was run</h2>" + what_was_run(info, trials) +
       operator_note(info) + "</section>";
  h += "<section id=\"result\"><h2>Result</h2><div class=\"cards\">";
  for (std::size_t k = 0; k < headline.groups.size(); ++k)
    h += card(headline.groups[k], k);
  h += "</div><div class=\"result\"><div class=\"words\">" + result_words(headline) +
       "<p>Trials: " + std::to_string(summary.trials_ok) + " finished and scored, " +
       std::to_string(summary.trials_failed) + " failed (listed below).</p></div>" +
       sai_chart_svg(headline) + "</div></section>";
  h += "<section id=\"sai\"><h2>Spatial Asymmetry Index per trial</h2>" +
       html::sai_table(info, trials, summary) + html::tests_table(summary) + "</section>";
  h += "<section id=\"heat-maps\"><h2>Representative heat maps</h2><p>Tool-tip positions "
       "projected onto the plane of the chest wall, coloured by density, as the paper's Fig. 13; "
       "each group is shown by its trial whose hook SAI is nearest the group's mean, with that "
       "trial's "
       "scene drawn at its start and at its end.</p>" +
       html::heat_maps(trials, summary) + "</section>";
  if (!images.empty() || !tables.empty()) {
    h += "<section id=\"history\"><h2>Trainee history</h2>";
    for (const ReportTable& table : tables)
      h += text_table_html(table);
    h += "<div class=\"figures\">";
    for (const ReportImage& image : images)
      h += html::figure(image.png_path, image.caption);
    h += "</div></section>";
  }
  h += "<section id=\"metrics\"><h2>Trainee metrics</h2><p>Each metric with its proficiency "
       "threshold (imasim's defaults for the built-in scene, not validated expert benchmarks)."
       "</p>" +
       html::metrics_table(summary) + html::metrics_per_trial_table(trials, summary) + "</section>";
  h += "<section id=\"failed\"><h2>Failed trials</h2>" + html::failed_trials(trials) + "</section>";
  h += "<section id=\"files\"><h2>Files</h2><p><code>results.json</code> (everything, "
       "machine-readable), <code>trials.csv</code> (one row a trial) and <code>trials/</code> "
       "(each trial's recording, side file, report and log) beside this page.</p></section>";
  h += "</main><footer>Generated by " + html_escape(info.program) +
       ". SAI: eq. 20 of Wang et al., \"A virtual simulation platform for robotic internal "
       "mammary artery harvesting\", as docs/scoring.md reads it.</footer><script>" +
       kReadyScript + "</script></body></html>\n";
  return h;
}

}  // namespace imasim::report
