#pragma once
// The study's statistics (metrics/statistics.hpp) over the trials that finished: per mode the
// mean and SD of each instrument's SAI and the trial nearest that mean (the representative one,
// as the paper's Fig. 13 shows representative heat maps); the first two modes compared by
// Welch's and Student's t-tests and Cohen's d; every trainee metric's mean, SD and pass rate per
// mode.
#include <optional>
#include <string>
#include <vector>

#include "metrics/statistics.hpp"
#include "report/study_data.hpp"

namespace imasim::report {

struct SaiGroup {
  std::string mode;
  std::vector<double> values;  // the finished trials', in trial order
  metrics::GroupSummary summary;
  int representative_trial = 0;  // the trial whose SAI is nearest the mean; 0 when none
};

struct SaiComparison {
  std::string instrument;
  std::vector<SaiGroup> groups;  // in the study's order of modes
  // The first two modes compared; unset with one mode or too few trials (then `test_problem`).
  std::optional<metrics::TwoGroupComparison> test;
  std::string test_problem;
};

struct MetricGroup {
  std::string mode;
  metrics::GroupSummary summary;
  std::size_t passed = 0;
};

struct MetricSummary {
  std::string name, unit;
  double threshold = 0;  // the first trial's (the same in every trial of a study)
  bool higher_is_better = false;
  std::vector<MetricGroup> groups;
};

struct StudySummary {
  std::vector<SaiComparison> sai;  // one per instrument, kInstruments' order
  std::vector<MetricSummary> metrics;
  std::size_t trials_ok = 0, trials_failed = 0;
};

StudySummary summarize_study(const std::vector<std::string>& modes,
                             const std::vector<TrialResult>& trials);

// The comparison of the headline instrument (kHeadlineInstrument).
const SaiComparison& headline_sai(const StudySummary& summary);

}  // namespace imasim::report
