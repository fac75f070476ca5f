#pragma once
// What `imasim history` reports of the trainee records (metrics/trainee_records.hpp), as one
// JSON object (the contract of `--json`, docs/scoring.md) and as the text printed from it:
//   {"database": PATH,
//    "metric": NAME,                          (only with --metric)
//    "trainees": [{"trainee": NAME,
//                  "sessions": [{"number", "id", "date_utc", "scene", "heart", "patient_seed",
//                                "operator", "input", "status", "recording",
//                                "sai": {"radius_m", "forceps": {...}, "hook": {...}},
//                                "metrics_passed", "metrics_total", "time_to_complete_s",
//                                "metrics": [{"name", "value", ...}]}],
//                  "progress": {"sessions", "first_passed", "first_total", "first_passed_share",
//                               "latest_passed", "latest_total", "latest_passed_share",
//                               "passed_share_trend_per_session",
//                               "first_time_to_complete_s", "latest_time_to_complete_s"},
//                  "series": {"metric", "unit", "better",
//                             "points": [{"number", "session_id", "date_utc", "value",
//                                         "threshold", "pass"}]}}]}   (series only with --metric)
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "metrics/trainee_records.hpp"

namespace imasim::cli {

// The report of `trainees` (each with a session); `metric` empty: no series.
nlohmann::ordered_json history_report(const metrics::TraineeRecords& records,
                                      const std::vector<std::string>& trainees,
                                      const std::string& metric);

// The report as text: per trainee a table of sessions (number, date, scene, heart, SAI forceps
// and hook, metrics passed of total, time to complete, status), a progress line and, with a
// metric, its series.
std::string history_text(const nlohmann::ordered_json& report);

}  // namespace imasim::cli
