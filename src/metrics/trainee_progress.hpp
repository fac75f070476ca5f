#pragma once
// A trainee's progress over recorded sessions (metrics/trainee_records.hpp): how many metrics
// each session passed, and the first against the latest with the trend between, as
// `imasim history` prints it and a report plots it.
#include <cstddef>
#include <optional>
#include <span>
#include <string_view>

#include "metrics/trainee_records.hpp"

namespace imasim::metrics {

struct PassCount {
  std::size_t passed = 0, total = 0;
  double share() const { return total == 0 ? 0.0 : double(passed) / double(total); }
};

PassCount pass_count(const SessionRecord& session);
// The session's metric or SAI of that name; null when it has none.
const TraineeMetric* find_metric(const SessionRecord& session, std::string_view name);
const SaiResult* find_sai(const SessionRecord& session, std::string_view instrument);

struct TraineeProgress {
  std::size_t sessions = 0;
  PassCount first, latest;
  // Least-squares slope of the passed share against the session number, 1, 2, ...
  // (unit: 1/session); 0 with fewer than two sessions.
  double passed_share_trend = 0;
  std::optional<double> first_time_to_complete_s, latest_time_to_complete_s;
};

// One trainee's sessions in date order (TraineeRecords::sessions).
TraineeProgress trainee_progress(std::span<const SessionRecord> sessions);

}  // namespace imasim::metrics
