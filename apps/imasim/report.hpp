#pragma once
// What the run-type subcommands share: the median of the step times and the summary, printed as
// one JSON object or as "key: value" lines.
#include <nlohmann/json.hpp>
#include <vector>

#include "physics/step.hpp"

namespace imasim::cli {

// Median of the values (reorders them); 0 for none.
double median(std::vector<double>& values);

// Adds "finite", "status" and, for a refused step, "failed_step" and "failed_particle".
void add_status(nlohmann::ordered_json& out, bool positions_finite,
                const physics::StepResult& failure, std::uint64_t steps_done);

// Mean milliseconds per step in each stage, and their sum, over the steps of `totals`.
nlohmann::ordered_json profile_report(const physics::ProfileTotals& totals);

// Prints to stdout and flushes; false when stdout did not take it (a full disk, a closed pipe).
bool print_report(const nlohmann::ordered_json& out, bool json);

}  // namespace imasim::cli
