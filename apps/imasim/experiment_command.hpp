#pragma once
// `imasim experiment --trials N --modes dynamic,static [--seed S] [--jobs J] [--out DIR]
// [--script FILE] [--seconds T] [--trial-timeout S] [--progress] [--json]`: a study of headless
// trials in parallel processes, reported in DIR/report.html, DIR/results.json and DIR/trials.csv
// (study_run.hpp, docs/scoring.md).
#include <CLI/CLI.hpp>
#include <memory>

#include "study_run.hpp"

namespace imasim::cli {

struct ExperimentOptions {
  StudyRequest request;
  double seconds = 0;  // with --script; 0 (not given): the run's default
  bool json = false;
  bool yes = false;  // start even when the estimate is over an hour or 10 GB
};

std::shared_ptr<ExperimentOptions> add_experiment_command(CLI::App& app);
int run_experiment_command(const ExperimentOptions& options);

}  // namespace imasim::cli
