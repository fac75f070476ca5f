#include "demo_command.hpp"

#include <iostream>

#include "cli_checks.hpp"
#include "study_records.hpp"

namespace imasim::cli {

namespace {

// A trial of the scripted operator is minutes of simulated surgery; one that runs for half an
// hour of wall-clock time has hung.
constexpr double kDemoTrialTimeout = 1800;

}  // namespace

std::shared_ptr<DemoOptions> add_demo_command(CLI::App& app) {
  auto opt = std::make_shared<DemoOptions>();
  StudyRequest& r = opt->request;
  r.modes = {"dynamic", "static"};
  r.trials = 3;
  r.out_dir = "out";
  r.progress = true;
  r.trial_timeout_s = kDemoTrialTimeout;
  r.who = "imasim demo";
  CLI::App* cmd = app.add_subcommand(
      "demo",
      "The main job: the scripted operator harvests the IMA with the beating and the "
      "static heart, and the study's report is written (out/report.html)");
  cmd->add_option("--trials", r.trials, "Trials per mode")
      ->capture_default_str()
      ->check(CLI::Range(2, 100));
  cmd->add_option("--out", r.out_dir, "Output folder")->capture_default_str()->check(non_empty());
  cmd->add_option("--jobs", r.jobs, "Trials at once (0 = the number of cores)")
      ->capture_default_str()
      ->check(CLI::Range(0, 256));
  add_study_records_options(*cmd, r.op);
  return opt;
}

int run_demo_command(const DemoOptions& o) {
  std::cerr << "imasim demo: " << o.request.trials
            << " trials each with the beating and the static heart, by the scripted operator "
               "(a test operator, not a model of surgeons)\n";
  const StudyOutcome outcome = run_study(o.request);
  if (outcome.exit_code == 2 || outcome.exit_code == 4) return outcome.exit_code;
  print_study_summary(std::cout, outcome);
  return outcome.exit_code;
}

}  // namespace imasim::cli
