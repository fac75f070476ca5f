#pragma once
// A study's trainee records: every scored trial is appended to the records like any
// recorded run (`--trainee`, `--db`, `--no-db` passed on to each trial), and the report shows the
// operator's history over all its sessions in those records (a plot per score).
#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

#include "report/study_data.hpp"
#include "trial_plan.hpp"

namespace imasim::cli {

// Registers --trainee, --db and --no-db on `experiment` or `demo`.
void add_study_records_options(CLI::App& cmd, OperatorChoice& op);

struct StudyHistory {
  std::vector<report::ReportTable> tables;  // the trainee's sessions, the latest last
  std::vector<report::ReportImage> images;  // the plots, drawn into the study's folder
};

// The history of `op.trainee` in the records the trials were appended to, this study's included
// (nothing with `no_db`, or when the records cannot be read: then `problem` says why).
StudyHistory study_history(const OperatorChoice& op, const std::string& dir, std::string& problem);

}  // namespace imasim::cli
