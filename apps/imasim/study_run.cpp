#include "study_run.hpp"

#include <ctime>
#include <filesystem>
#include <iostream>
#include <thread>

#include "interrupt.hpp"
#include "math/text_file.hpp"
#include "metrics/output_file.hpp"
#include "report/text_format.hpp"
#include "study_progress.hpp"
#include "study_records.hpp"
#include "surgery/input_script.hpp"
#include "trial_manifest.hpp"
#include "trial_processes.hpp"

namespace imasim::cli {

namespace {

// A side file holds the run's description and scores: kilobytes.
constexpr std::uint64_t kMaxSideFileBytes = 64ull << 20;
constexpr std::uint64_t kMaxLogBytes = 64ull << 20;

std::string utc_now() {
  const std::time_t now = std::time(nullptr);
  std::tm parts{};
  gmtime_r(&now, &parts);
  char text[32];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", &parts);
  return text;
}

// The last line the child wrote on stderr, usually why it failed (CLI11's closing hint
// "Run with --help ..." skipped: the line before it says what was wrong).
std::string last_log_line(const std::string& path) {
  const TextFile log = read_text_file(path, kMaxLogBytes, "trial's log");
  std::string line;
  std::size_t start = 0;
  while (start < log.text.size()) {
    std::size_t end = log.text.find('\n', start);
    if (end == std::string::npos) end = log.text.size();
    const std::string current = log.text.substr(start, end - start);
    if (!current.empty() && !current.starts_with("Run with --help")) line = current;
    start = end + 1;
  }
  if (line.size() > 200) line = line.substr(0, 200) + "...";
  return line;
}

report::StudyInfo study_info(const StudyRequest& r, int jobs) {
  report::StudyInfo info;
  info.program = "imasim " IMASIM_VERSION;
  info.scene = "built-in thorax";
  info.modes = r.modes;
  info.trials_per_mode = r.trials;
  info.seed = r.seed;
  info.operator_kind = r.op.script_file.empty() ? "autopilot" : "script";
  info.operator_description =
      r.op.script_file.empty()
          ? "the scripted operator (autopilot), one operator seed per trial number"
          : "the input script " + r.op.script_file + ", the same in every trial";
  info.script = r.op.script_file;
  info.seconds = r.op.seconds;
  info.jobs = jobs;
  info.trial_timeout_s = r.trial_timeout_s;
  info.date = utc_now();
  info.status = "complete";
  return info;
}

// How the run says it ended, from its report (its stdout): "the simulation refused step N
// (speed_limit)" and the like; empty when the report is missing or says "ok".
std::string run_status_of(const std::string& report_path) {
  const TextFile text = read_text_file(report_path, kMaxSideFileBytes, "trial's report");
  if (!text.error.empty()) return "";
  const nlohmann::json j = nlohmann::json::parse(text.text, nullptr, false);
  if (!j.is_object() || !j.contains("status") || !j["status"].is_string()) return "";
  const std::string status = j["status"].get<std::string>();
  if (status == "ok") return "";
  std::string said = "the run ended with status " + status;
  if (j.contains("failed_step") && j["failed_step"].is_number_unsigned())
    said += " at step " + std::to_string(j["failed_step"].get<std::uint64_t>());
  return said;
}

report::TrialResult trial_result(const TrialPlan& plan, const TrialExit& exit,
                                 const StudyRequest& r) {
  report::TrialResult t;
  t.mode = plan.mode;
  t.trial = plan.trial;
  t.patient_seed = plan.patient_seed;
  if (r.op.script_file.empty()) t.operator_seed = plan.operator_seed;
  t.wall_s = exit.wall_s;
  t.files = {{"recording", plan.recording},
             {"side", plan.side},
             {"report", plan.report},
             {"log", plan.log}};
  if (!exit.ok()) {
    t.reason = exit.describe(r.trial_timeout_s);
    if (exit.end == TrialExit::End::exited || exit.end == TrialExit::End::signalled) {
      if (const std::string status = run_status_of(plan.report); !status.empty())
        t.reason += ": " + status;
      else if (const std::string line = last_log_line(plan.log); !line.empty())
        t.reason += ": " + line;
    }
    return t;
  }
  const TextFile side = read_text_file(plan.side, kMaxSideFileBytes, "trial's side file");
  try {
    if (!side.error.empty()) throw report::StudyDataError(plan.side + ": " + side.error);
    report::read_trial_scores(side.text, plan.side, t);
    t.ok = true;
  } catch (const report::StudyDataError& e) {
    t.reason = std::string("no scores: ") + e.what();
  }
  return t;
}

}  // namespace

StudyOutcome run_study(const StudyRequest& r) {
  StudyOutcome outcome;
  const int jobs = r.jobs > 0 ? r.jobs : int(std::max(1u, std::thread::hardware_concurrency()));
  outcome.info = study_info(r, jobs);
  if (!r.op.script_file.empty()) {
    try {
      static_cast<void>(surgery::load_input_script(r.op.script_file));
    } catch (const surgery::InputScriptError& e) {
      std::cerr << e.what() << '\n';
      outcome.exit_code = 2;
      return outcome;
    }
  }
  std::error_code ec;
  std::filesystem::create_directories(r.out_dir + "/trials", ec);
  if (ec) {
    std::cerr << r.who << ": cannot create the output folder " << r.out_dir
              << "/trials: " << ec.message() << '\n';
    outcome.exit_code = 2;
    return outcome;
  }
  const std::vector<TrialPlan> plans = plan_trials(r.modes, r.trials, r.seed, r.out_dir);
  // A trial an earlier run of this study finished, its files unchanged, is kept; the rest run.
  std::vector<TrialExit> exits(plans.size());
  std::vector<std::vector<std::string>> arguments;
  std::vector<std::size_t> to_run;
  std::vector<TrialProcess> processes;
  for (std::size_t i = 0; i < plans.size(); ++i) {
    arguments.push_back(trial_arguments(plans[i], r.op));
    if (const std::optional<double> wall = kept_trial(plans[i], arguments[i])) {
      exits[i].end = TrialExit::End::exited;
      exits[i].exit_code = 0;
      exits[i].wall_s = *wall;
      ++outcome.trials_kept;
      continue;
    }
    std::filesystem::remove(manifest_path(plans[i]), ec);  // a failed rerun must not look kept
    to_run.push_back(i);
    processes.push_back({arguments[i], plans[i].report, plans[i].log});
  }
  if (outcome.trials_kept > 0)
    std::cerr << r.who << ": " << outcome.trials_kept << " of " << plans.size()
              << " trials kept from an earlier run of this study in " << r.out_dir
              << " (their files unchanged); running the other " << to_run.size() << '\n';
  install_interrupt_handlers();
  StudyProgress progress(r.progress, std::cerr);
  // Each trial's manifest as it ends: a study killed later keeps what finished.
  const auto keep = [&](std::size_t k, const TrialExit& e) {
    if (!e.ok()) return;
    try {
      write_trial_manifest(plans[to_run[k]], arguments[to_run[k]], e.wall_s);
    } catch (const metrics::OutputError& error) {
      std::cerr << r.who << ": note: the trial will run again in a rerun: " << error.what() << '\n';
    }
  };
  const std::vector<TrialExit> ran = run_trial_processes(
      processes, jobs, r.trial_timeout_s, [&](const TrialCounts& c) { progress.update(c); }, keep);
  progress.finish();
  for (std::size_t k = 0; k < to_run.size(); ++k)
    exits[to_run[k]] = ran[k];
  for (std::size_t i = 0; i < plans.size(); ++i)
    outcome.trials.push_back(trial_result(plans[i], exits[i], r));
  outcome.summary = report::summarize_study(r.modes, outcome.trials);
  const int signal = interrupt_signal();
  if (signal != 0) outcome.info.status = "interrupted";
  std::string history_problem;
  const StudyHistory history = study_history(r.op, r.out_dir, history_problem);
  if (!history_problem.empty())
    std::cerr << r.who << ": note: no trainee history in the report: " << history_problem << '\n';
  try {
    outcome.files = report::write_study_files(r.out_dir, outcome.info, outcome.trials,
                                              outcome.summary, history.images, history.tables);
  } catch (const metrics::OutputError& e) {
    std::cerr << r.who << ": " << e.what() << '\n';
    outcome.exit_code = 4;
    return outcome;
  }
  outcome.exit_code = signal != 0 ? interrupted_exit_status(signal) : 0;
  return outcome;
}

nlohmann::ordered_json study_summary_json(const StudyOutcome& o) {
  nlohmann::ordered_json j;
  j["status"] = o.info.status;
  j["report"] = o.files.report_html;
  j["results"] = o.files.results_json;
  j["trials_csv"] = o.files.trials_csv;
  j["trials"] = o.trials.size();
  j["trials_kept"] = o.trials_kept;
  j["trials_ok"] = o.summary.trials_ok;
  j["trials_failed"] = o.summary.trials_failed;
  const report::SaiComparison& headline = report::headline_sai(o.summary);
  nlohmann::ordered_json groups;
  for (const report::SaiGroup& g : headline.groups)
    groups[g.mode] = {{"n", g.summary.n}, {"mean", g.summary.mean}, {"sd", g.summary.sd}};
  j["sai_hook"] = groups;
  if (headline.test) {
    j["p_welch"] = headline.test->welch.p;
    j["p_student"] = headline.test->student.p;
    j["cohen_d"] = headline.test->cohen_d;
  } else {
    j["test_problem"] = headline.test_problem;
  }
  return j;
}

void print_study_summary(std::ostream& out, const StudyOutcome& o) {
  out << "Study: " << o.trials.size() << " trials (" << o.info.trials_per_mode << " per mode), "
      << o.summary.trials_ok << " finished, " << o.summary.trials_failed << " failed"
      << (o.info.status == "complete" ? "" : " (interrupted)") << '\n';
  const report::SaiComparison& headline = report::headline_sai(o.summary);
  out << "  SAI of the hook (the headline instrument):";
  for (const report::SaiGroup& g : headline.groups)
    out << "  " << g.mode << " "
        << (g.values.empty() ? std::string("-") : report::mean_sd(g.summary.mean, g.summary.sd, 3))
        << " (n = " << g.values.size() << ")";
  out << '\n';
  if (headline.test)
    out << "  Welch's t = " << report::fixed(headline.test->welch.t, 2) << ", df "
        << report::fixed(headline.test->welch.df, 1) << ", "
        << report::p_text(headline.test->welch.p)
        << "; Cohen's d = " << report::fixed(headline.test->cohen_d, 2) << '\n';
  else
    out << "  No test: " << headline.test_problem << '\n';
  for (const report::TrialResult& t : o.trials)
    if (!t.ok) out << "  failed: " << t.mode << " trial " << t.trial << ": " << t.reason << '\n';
  out << "Report: " << o.files.report_html << '\n';
}

}  // namespace imasim::cli
