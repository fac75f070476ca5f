#pragma once
// The study's outputs in its folder: report.html (study_html.hpp), results.json (everything,
// machine-readable; keys in docs/scoring.md) and trials.csv (one row a trial; pandas reads it with
// no options). Every write and close is checked (metrics/output_file.hpp).
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "report/study_data.hpp"
#include "report/study_summary.hpp"

namespace imasim::report {

nlohmann::ordered_json study_results_json(const StudyInfo& info,
                                          const std::vector<TrialResult>& trials,
                                          const StudySummary& summary);

std::string trials_csv(const std::vector<TrialResult>& trials, const StudySummary& summary);

struct StudyFiles {
  std::string report_html, results_json, trials_csv;
};

// Writes the three files into `dir` (which exists). Throws metrics::OutputError.
StudyFiles write_study_files(const std::string& dir, const StudyInfo& info,
                             const std::vector<TrialResult>& trials, const StudySummary& summary,
                             const std::vector<ReportImage>& images = {},
                             const std::vector<ReportTable>& tables = {});

}  // namespace imasim::report
