#pragma once
// What makes a finished trial of a study worth keeping: a manifest written beside its
// files when it ends well, DIR/trials/<mode>-<NN>.done.json, with the trial's command line and a
// hash of each of its files. A rerun of the study with the same --out keeps a trial whose manifest
// matches its command line and whose files still hash the same, and runs only the others: a study
// killed part-way resumes, and no kept trial is recorded twice in the trainee records.
#include <optional>
#include <string>
#include <vector>

#include "trial_plan.hpp"

namespace imasim::cli {

std::string manifest_path(const TrialPlan& plan);

// Writes the manifest of a trial that ended well (throws metrics::OutputError).
void write_trial_manifest(const TrialPlan& plan, const std::vector<std::string>& arguments,
                          double wall_s);

// The kept trial's wall-clock time, or empty (no manifest, another command line, a file changed
// or missing: the trial runs again).
std::optional<double> kept_trial(const TrialPlan& plan, const std::vector<std::string>& arguments);

}  // namespace imasim::cli
