#include "experiment_command.hpp"

#include <iostream>

#include "cli_checks.hpp"
#include "report.hpp"
#include "study_records.hpp"

namespace imasim::cli {

namespace {

// A study of a thousand trials per mode is days of computing: more is a typing error.
constexpr int kMaxTrials = 1000;
constexpr double kMaxTrialSeconds = 3600;  // as `run --seconds`

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
