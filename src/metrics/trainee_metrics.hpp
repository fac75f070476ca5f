#pragma once
// Trainee metrics of a recorded session, as robotic-surgery simulators report them,
// each against a proficiency threshold with pass or fail. Computed from the 60 Hz recording
// (metrics/trajectory_recorder.hpp), the event stream and the session's totals. Between two
// rows the state of the earlier one holds; speeds are the tip's displacement between rows over
// their time apart. The thresholds are documented defaults (docs/scoring.md), not validated
// expert benchmarks; a study overrides them by name.
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "metrics/spatial_asymmetry.hpp"
#include "metrics/trajectory_recorder.hpp"
#include "surgery/events.hpp"

namespace imasim::metrics {

struct SessionTotals {
  std::uint64_t strands_total = 0, strands_cut = 0;
  Real ima_radius = Real(0.0015);  // the vessel's outer radius (unit: m)
};

struct MetricLimits {
  Real idle_speed = Real(0.001);          // a tip slower than this is idle (unit: m/s)
  Real force_threshold = Real(2.5);       // "time above force" counts above this (unit: N)
  Real excessive_force = Real(4.0);       // an excessive-force event starts above this (unit: N)
  Real collision_distance = Real(0.005);  // tips closer than this collide (unit: m)
  Real energy_margin = Real(0.002);       // cautery on within the IMA's radius + this (unit: m)
};

struct TraineeMetric {
  std::string name, unit, meaning;
  double value = 0;
  double threshold = 0;
  bool higher_is_better = false;  // else lower is better (at most the threshold passes)
  bool pass = false;
};

class MetricsError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The metrics' names, in the order trainee_metrics gives them.
std::vector<std::string> trainee_metric_names();

// Every metric in a fixed order. `overrides` replaces thresholds by metric name (MetricsError
// for a name that is not a metric or a value that is not finite).
std::vector<TraineeMetric> trainee_metrics(std::span<const TrajectorySample> rows,
                                           const surgery::EventLog& events,
                                           const SideReference& ima, const SessionTotals& totals,
                                           const MetricLimits& limits = {},
                                           const std::map<std::string, double>& overrides = {});

}  // namespace imasim::metrics
