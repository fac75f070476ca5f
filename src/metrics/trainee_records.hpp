#pragma once
// Trainee records: every scored session appended to one SQLite database, so that an
// educator sees a trainee's progress over sessions (`imasim history`). One row a session
// (trainee, UTC date-time, scene, heart mode, patient seed, operator, SAI per instrument) and
// one a metric, in the order trainee_metrics gives them. Several processes of a study may append
// at once: the database is in WAL mode, a writer waits for another's lock (busy timeout) and a
// session goes in as one transaction, whole or not at all. The schema is versioned (PRAGMA
// application_id marks the file as imasim's, PRAGMA user_version its schema); a file of another
// program, a newer schema or a file that is not SQLite is refused naming the file.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "metrics/spatial_asymmetry.hpp"
#include "metrics/sqlite_database.hpp"
#include "metrics/trainee_metrics.hpp"

namespace imasim::metrics {

// The schema this program writes and reads (PRAGMA user_version).
inline constexpr std::int64_t kRecordsSchemaVersion = 1;
// PRAGMA application_id of imasim's records: "IMAS" in ASCII.
inline constexpr std::int64_t kRecordsApplicationId = 0x494D4153;
// How long an append waits for another process's write lock (unit: ms).
inline constexpr int kRecordsBusyTimeoutMs = 30000;
// At a session's end the append waits this long; a lock held longer does not cost the session:
// it is held in a file of its own beside the records (PATH.pending-...sqlite), which the next
// append-mode open adds (unit: ms).
inline constexpr int kRecordsAppendWaitMs = 5000;
// Before a session, how long the test for writing waits for another process's lock (unit: ms).
inline constexpr int kRecordsCheckWaitMs = 1000;
inline constexpr const char* kPendingInfix = ".pending-";
inline constexpr const char* kPendingSuffix = ".sqlite";

// Where a session went: its row id, or (id 0) the pending file holding it.
struct AppendResult {
  std::int64_t id = 0;
  std::string pending;
};

enum class HeartMode { dynamic, static_heart };
// Who moved the instruments: a person at devices, an input script (or emulated devices playing
// one), the scripted operator (autopilot), or a replayed input stream.
enum class OperatorKind { human_device, script, scripted_operator, replay };

const char* to_string(HeartMode mode);  // "dynamic", "static"
const char* to_string(
    OperatorKind kind);  // "human_device", "script", "scripted_operator", "replay"
std::optional<HeartMode> heart_mode_from(const std::string& text);
std::optional<OperatorKind> operator_kind_from(const std::string& text);

struct InstrumentSai {
  std::string instrument;  // "forceps", "hook"
  SaiResult result;
};

struct SessionRecord {
  std::int64_t id = 0;   // the database's row id: set by append_session and by the queries
  std::string trainee;   // checked by trainee_name_problem
  std::string date_utc;  // ISO 8601, "2025-03-01T14:05:09Z" (utc_timestamp)
  std::string scene;     // the scene file, or "built-in thorax"
  HeartMode heart = HeartMode::dynamic;
  std::uint64_t patient_seed = 0;  // at most INT64_MAX (SQLite's integers are signed)
  OperatorKind operator_kind = OperatorKind::script;
  std::string input;               // the input in detail: "script", "openigtlink", "emulator", ...
  std::string status;              // how the run ended: "ok", "interrupted", ...
  std::string recording;           // the recording's CSV file (may be empty)
  double sai_radius = kSaiRadius;  // R of eq. 20 (unit: m)
  std::vector<InstrumentSai> sai;  // one per instrument, names unique
  std::vector<TraineeMetric> metrics;  // in trainee_metrics' order, names unique
};

// One session's value of one metric: a point of a trainee's progress plot.
struct HistoryPoint {
  std::int64_t session_number = 0;  // 1 for the trainee's first session (by date)
  std::int64_t session_id = 0;
  std::string date_utc;
  double value = 0, threshold = 0;
  bool pass = false;
};

struct MetricHistory {
  std::string trainee, metric, unit;
  bool higher_is_better = false;     // of the latest session
  std::vector<HistoryPoint> points;  // in date order; sessions without the metric are skipped
};

class TraineeRecords {
 public:
  enum class Access {
    append,    // created if missing (its directory must exist), the schema written if new
    read_only  // must exist; a database with no sessions yet reads as empty
  };

  // Throws RecordsError naming `path`: not a regular file, cannot be opened or created, not
  // SQLite, another program's database, a newer schema; for append also write-protected or
  // damaged (PRAGMA quick_check), so that a session is not spent for records that cannot take
  // it. Opened for append it adds the sessions held pending beside it (notes() says so).
  TraineeRecords(const std::string& path, Access access);

  // Appends the session in one transaction; returns its row id. Refuses (RecordsError, nothing
  // written) a bad trainee name or date, an empty scene, repeated metric or instrument names,
  // a value that is not finite.
  std::int64_t append_session(const SessionRecord& session);
  // As append_session, waiting at most `wait_ms` for another process's lock; past it the session
  // is held in a pending file beside the records instead (RecordsError as above).
  AppendResult append_or_hold(const SessionRecord& session, int wait_ms = kRecordsAppendWaitMs);

  // Sessions in date order (then in the order appended), with their SAI and metrics; of one
  // trainee, or of everyone when `trainee` is empty.
  std::vector<SessionRecord> sessions(const std::string& trainee = {}) const;
  // Every trainee with a session, sorted by name (bytewise).
  std::vector<std::string> trainees() const;
  // One metric's values over one trainee's sessions.
  MetricHistory metric_history(const std::string& trainee, const std::string& metric) const;

  const std::string& path() const { return db_->path(); }
  // What opening did on the user's behalf (held sessions added, a held file left), to be said.
  const std::vector<std::string>& notes() const { return notes_; }
  std::size_t imported_pending() const { return imported_; }

 private:
  void prepare_schema(Access access);
  void check_before_work();
  void import_pending();
  std::int64_t insert_session(const SessionRecord& session);  // inside the caller's transaction

  std::unique_ptr<SqliteDatabase> db_;
  bool has_schema_ = false;  // false: a new, empty database opened read-only
  std::vector<std::string> notes_;
  std::size_t imported_ = 0;
};

// The current time as ISO 8601 UTC to the second ("2025-03-01T14:05:09Z").
std::string utc_timestamp();
// Empty when `text` is such a time (a real calendar date), else why not.
std::string timestamp_problem(const std::string& text);

}  // namespace imasim::metrics
