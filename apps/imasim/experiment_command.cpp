#include "experiment_command.hpp"

#include <algorithm>
#include <iostream>
#include <sstream>
#include <thread>

#include "cli_checks.hpp"
#include "job_estimate.hpp"
#include "report.hpp"
#include "study_records.hpp"
#include "surgery/input_script.hpp"

namespace imasim::cli {

namespace {

// A study of a thousand trials per mode is days of computing: more is a typing error.
constexpr int kMaxTrials = 1000;
constexpr double kMaxTrialSeconds = 3600;  // as `run --seconds`
// The scripted operator's harvest at its defaults (docs/autopilot.md) (unit: s).
constexpr double kAutopilotHarvestSeconds = 131;

std::string shortest_seconds(double s) {
  std::ostringstream out;
  out << s;
  return out.str();
}

}  // namespace

std::shared_ptr<ExperimentOptions> add_experiment_command(CLI::App& app) {
  auto opt = std::make_shared<ExperimentOptions>();
  StudyRequest& r = opt->request;
  r.modes.clear();
  CLI::App* cmd = app.add_subcommand(
      "experiment",
      "Run a study: headless trials in parallel processes, per mode, and its report "
      "(report.html, results.json, trials.csv)");
  cmd->add_option("--trials", r.trials, "Trials per mode")
      ->required()
      ->check(CLI::Range(1, kMaxTrials));
  cmd->add_option("--modes", r.modes, "Heart modes, comma-separated: dynamic, static")
      ->required()
      ->delimiter(',')
      ->check(CLI::IsMember({"dynamic", "static"}));
  cmd->add_option("--seed", r.seed,
                  "Study seed: each trial's patient and operator seed derive from it and the "
                  "trial's number (trial k is the same patient in every mode)")
      ->capture_default_str()
      ->check(unsigned_at_most(UINT64_MAX));
  cmd->add_option("--jobs", r.jobs, "Trials at once (0 = the number of cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, 256));
  cmd->add_option("--out", r.out_dir, "Output folder (created; trials go to DIR/trials)")
      ->capture_default_str()
      ->check(non_empty());
  cmd->add_option("--script", r.op.script_file,
                  "Play this input script in every trial instead of the scripted operator")
      ->check(non_empty());
  cmd->add_option("--seconds", opt->seconds, "Simulated time of each trial (s)")
      ->check(finite_range(0.01, kMaxTrialSeconds));
  cmd->add_option("--trial-timeout", r.trial_timeout_s,
                  "Kill a trial after this many seconds of wall-clock time and report it failed "
                  "(0 = no limit)")
      ->capture_default_str()
      ->check(finite_range(0, 7 * 86400.0));
  cmd->add_flag("--progress", r.progress,
                "Show the progress bar on stderr even when it is not a terminal");
  add_study_records_options(*cmd, r.op);
  cmd->add_flag("--json", opt->json, "Print the summary as one JSON object on stdout");
  cmd->add_flag("--yes", opt->yes, "Start even when the estimate is over an hour or 10 GB");
  return opt;
}

int run_experiment_command(const ExperimentOptions& o) {
  StudyRequest r = o.request;
  for (std::size_t i = 0; i < r.modes.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (r.modes[i] == r.modes[j]) {
        std::cerr << "imasim experiment: --modes names '" << r.modes[i] << "' twice\n";
        return 2;
      }
  if (o.seconds > 0) r.op.seconds = o.seconds;
  // Each trial's simulated time: --seconds, else the script's, else the scripted operator's
  // harvest at its defaults (docs/autopilot.md).
  double trial_s = kAutopilotHarvestSeconds;
  if (r.op.seconds) {
    trial_s = *r.op.seconds;
  } else if (!r.op.script_file.empty()) {
    try {
      trial_s = surgery::load_input_script(r.op.script_file).end_time() + 0.5;
    } catch (const surgery::InputScriptError&) {
      // run_study says what is wrong with it
    }
  }
  const int jobs = r.jobs > 0 ? r.jobs : int(std::max(1u, std::thread::hardware_concurrency()));
  const std::uint64_t trials = std::uint64_t(r.trials) * r.modes.size();
  if (!confirm_job("imasim experiment",
                   std::to_string(trials) + " trials of " + shortest_seconds(trial_s) + " s, " +
                       std::to_string(jobs) + " at once",
                   study_estimate(trials, trial_s, jobs), o.yes, std::cerr))
    return 2;
  const StudyOutcome outcome = run_study(r);
  if (outcome.exit_code == 2 || outcome.exit_code == 4) return outcome.exit_code;
  if (o.json) {
    if (!print_report(study_summary_json(outcome), true)) return 4;
  } else {
    print_study_summary(std::cout, outcome);
  }
  return outcome.exit_code;
}

}  // namespace imasim::cli
