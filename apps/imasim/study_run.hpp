#pragma once
// A study as `imasim experiment` and `imasim demo` run it: the trials as child processes
// (trial_processes.hpp), their scores read from each recording's side file, the statistics and
// the report written into the output folder (report/study_files.hpp), and a short summary.
#include <cstdint>
#include <iosfwd>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "report/study_files.hpp"
#include "report/study_summary.hpp"
#include "trial_plan.hpp"

namespace imasim::cli {

struct StudyRequest {
  std::vector<std::string> modes;  // "dynamic", "static"
  int trials = 3;                  // per mode
  std::uint64_t seed = 1;
  int jobs = 0;  // 0: the number of cores
  std::string out_dir = "out";
  OperatorChoice op;
  double trial_timeout_s = 0;             // 0: no limit (unit: s of wall-clock time)
  bool progress = false;                  // the progress bar even when stderr is no terminal
  std::string who = "imasim experiment";  // starts messages
};

struct StudyOutcome {
  // 0 the report was written (failed trials are in it), 2 a bad request, 4 an output could not
  // be written, 128 + the signal that stopped the study (its report covers what finished).
  int exit_code = 0;
  report::StudyInfo info;
  std::vector<report::TrialResult> trials;
  report::StudySummary summary;
  report::StudyFiles files;
  // Trials kept from an earlier run of the study in the same folder (trial_manifest.hpp).
  std::size_t trials_kept = 0;
};

StudyOutcome run_study(const StudyRequest& request);

// The summary as one JSON object: the files, the counts, the headline SAI per group, the test.
nlohmann::ordered_json study_summary_json(const StudyOutcome& outcome);

// The same for a person: a few lines.
void print_study_summary(std::ostream& out, const StudyOutcome& outcome);

}  // namespace imasim::cli
