#pragma once
// The sections of the study's page (study_html.cpp puts them together).
#include <string>
#include <vector>

#include "report/study_data.hpp"
#include "report/study_summary.hpp"

namespace imasim::report::html {

// "the beating heart" for dynamic, "the static heart" for static, else the mode's name.
std::string mode_phrase(const std::string& mode);

// Trial `number` of `mode`; null when there is none.
const TrialResult* find_trial(const std::vector<TrialResult>& trials, const std::string& mode,
                              int number);

// A number as tables show it: up to four significant digits, whole numbers without a point.
std::string short_number(double v);

// A PNG file as a <figure> with its data URI, or a note naming the file and what is wrong.
std::string figure(const std::string& png_path, const std::string& caption);

std::string sai_table(const StudyInfo& info, const std::vector<TrialResult>& trials,
                      const StudySummary& summary);
std::string tests_table(const StudySummary& summary);
std::string metrics_table(const StudySummary& summary);
std::string metrics_per_trial_table(const std::vector<TrialResult>& trials,
                                    const StudySummary& summary);
std::string failed_trials(const std::vector<TrialResult>& trials);
std::string heat_maps(const std::vector<TrialResult>& trials, const StudySummary& summary);

}  // namespace imasim::report::html
