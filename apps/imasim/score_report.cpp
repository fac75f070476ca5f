#include "score_report.hpp"

namespace imasim::cli {

nlohmann::ordered_json sai_report(const metrics::SaiResult& r) {
  return {{"sai", r.sai},
          {"samples", r.samples},
          {"mean_distance_m", r.mean_distance},
          {"heart_side_fraction", r.heart_side_fraction}};
}

nlohmann::ordered_json metric_report(const metrics::TraineeMetric& m) {
  return {{"name", m.name},
          {"value", m.value},
          {"unit", m.unit},
          {"threshold", m.threshold},
          {"better", m.higher_is_better ? "higher" : "lower"},
          {"pass", m.pass},
          {"meaning", m.meaning}};
}

}  // namespace imasim::cli
