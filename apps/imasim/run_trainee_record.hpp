#pragma once
// `imasim run --record FILE.csv` appends its scored session to the trainee records
// (metrics/trainee_records.hpp): --trainee NAME (default: $USER, else "anonymous"), --db PATH
// (default: metrics/records_path.hpp), --no-db to skip. The database is opened before the run,
// so that a bad one is refused before a session is spent, and appended to at its end.
#include <nlohmann/json.hpp>
#include <string>

#include "metrics/trainee_records.hpp"
#include "run_recording.hpp"

namespace imasim::cli {

struct RecordsChoice {
  std::string trainee, database;
};

// --trainee or $USER or "anonymous"; --db or the default path (its directory created). Throws
// metrics::RecordsError: a bad name (saying where it came from), no place for the database.
RecordsChoice choose_records(const std::string& trainee_option, const std::string& db_option);

// Who moved the instruments, from run's --devices (resolved: "script" for --script) and --replay.
metrics::OperatorKind operator_kind_of(const std::string& devices, bool replay);

// Appends `session` (who, when, what was run) with the recording's scores, notes where in the
// recording's side file and returns the same note for the run's report: {"database", "session_id",
// "trainee"}; when another process held the records locked past kRecordsAppendWaitMs, the session
// is held pending beside them ("session_id" null, "pending": the file) for the next recorded run
// to add. Throws metrics::RecordsError, metrics::OutputError.
nlohmann::ordered_json append_trainee_record(metrics::TraineeRecords& records,
                                             RunRecording& recording,
                                             metrics::SessionRecord session);

}  // namespace imasim::cli
