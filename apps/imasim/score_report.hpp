#pragma once
// Scores as the command line reports them, the same in `run --record`'s report and side file
// and in `imasim history`: an instrument's SAI and a trainee metric as JSON objects.
#include <nlohmann/json.hpp>

#include "metrics/spatial_asymmetry.hpp"
#include "metrics/trainee_metrics.hpp"

namespace imasim::cli {

// {"sai", "samples", "mean_distance_m", "heart_side_fraction"}
nlohmann::ordered_json sai_report(const metrics::SaiResult& r);

// {"name", "value", "unit", "threshold", "better": "higher"|"lower", "pass", "meaning"}
nlohmann::ordered_json metric_report(const metrics::TraineeMetric& m);

}  // namespace imasim::cli
