#include "trainee_records.hpp"

#include <sqlite3.h>

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <limits>
#include <set>

#include "math/printable.hpp"
#include "metrics/trainee_name.hpp"

namespace imasim::metrics {

namespace {

constexpr const char* kSchema = R"sql(
CREATE TABLE sessions (
  id INTEGER PRIMARY KEY,
  trainee TEXT NOT NULL,
  date_utc TEXT NOT NULL,
  scene TEXT NOT NULL,
  heart TEXT NOT NULL,
  patient_seed INTEGER NOT NULL,
  operator TEXT NOT NULL,
  input TEXT NOT NULL,
  status TEXT NOT NULL,
  recording TEXT NOT NULL,
  sai_radius_m REAL NOT NULL
);
CREATE INDEX sessions_by_trainee ON sessions (trainee, date_utc, id);
CREATE TABLE session_sai (
  session_id INTEGER NOT NULL REFERENCES sessions (id),
  position INTEGER NOT NULL,
  instrument TEXT NOT NULL,
  sai REAL NOT NULL,
  samples INTEGER NOT NULL,
  mean_distance_m REAL NOT NULL,
  heart_side_fraction REAL NOT NULL,
  PRIMARY KEY (session_id, position)
);
CREATE TABLE session_metrics (
  session_id INTEGER NOT NULL REFERENCES sessions (id),
  position INTEGER NOT NULL,
  name TEXT NOT NULL,
  unit TEXT NOT NULL,
  meaning TEXT NOT NULL,
  value REAL NOT NULL,
  threshold REAL NOT NULL,
  higher_is_better INTEGER NOT NULL,
  pass INTEGER NOT NULL,
  PRIMARY KEY (session_id, position)
);
CREATE INDEX metrics_by_name ON session_metrics (name, session_id);
)sql";

// Switches the file to WAL, so readers and one writer of several processes work at once. The
// switch needs the file to itself; a process that opens the database beside another retries
// until the busy timeout (SQLite does not wait for this lock itself).
void use_write_ahead_log(SqliteDatabase& db) {
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::milliseconds(kRecordsBusyTimeoutMs);
  // A file system without WAL keeps its journal: still correct, only slower.
  while (!db.execute_unless_busy("PRAGMA journal_mode=WAL", "switching to WAL mode")) {
    if (std::chrono::steady_clock::now() > deadline)
      throw RecordsError(db.path() +
                         ": switching to WAL mode: still locked by another process "
                         "after " +
                         std::to_string(kRecordsBusyTimeoutMs / 1000) + " s");
    sqlite3_sleep(10);
  }
}

// Commits on commit(); else rolls back, so a failed append leaves no half session.
class Transaction {
 public:
  explicit Transaction(SqliteDatabase& db) : db_(db) {
    // IMMEDIATE takes the write lock at once (waiting the busy timeout), instead of failing
    // at the first write when another process wrote meanwhile.
    db_.execute("BEGIN IMMEDIATE", "starting a transaction");
  }
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  ~Transaction() {
    if (open_) rollback();
  }
  void commit() {
    db_.execute("COMMIT", "committing");
    open_ = false;
  }

 private:
  void rollback() noexcept {
    try {
      db_.execute("ROLLBACK", "rolling back");
    } catch (const RecordsError&) {
      // SQLite rolls back by itself when the connection closes; nothing more to do here.
    }
  }
  SqliteDatabase& db_;
  bool open_ = true;
};

void check_finite(double v, const std::string& what, const std::string& path) {
  if (!std::isfinite(v))
    throw RecordsError(path + ": cannot record " + what + ": " + std::to_string(v) +
                       " is not a finite number");
}

void check_session(const SessionRecord& s, const std::string& path) {
  const auto refuse = [&](const std::string& why) {
    throw RecordsError(path + ": cannot record the session: " + why);
  };
  if (const std::string problem = trainee_name_problem(s.trainee); !problem.empty())
    refuse("the trainee's name " + problem);
  if (const std::string problem = timestamp_problem(s.date_utc); !problem.empty())
    refuse("the date " + problem);
  if (s.scene.empty()) refuse("no scene named");
  if (s.patient_seed > std::uint64_t(std::numeric_limits<std::int64_t>::max()))
    refuse("patient seed " + std::to_string(s.patient_seed) + " is above 2^63 - 1");
  check_finite(s.sai_radius, "the SAI radius", path);
  std::set<std::string> names;
  for (const InstrumentSai& i : s.sai) {
    if (i.instrument.empty() || !names.insert(i.instrument).second)
      refuse("instrument name '" + i.instrument + "' empty or repeated");
    check_finite(double(i.result.sai), "the SAI of " + i.instrument, path);
    check_finite(double(i.result.mean_distance), "the mean distance of " + i.instrument, path);
    check_finite(double(i.result.heart_side_fraction), "the heart side of " + i.instrument, path);
  }
  names.clear();
  for (const TraineeMetric& m : s.metrics) {
    if (m.name.empty() || !names.insert(m.name).second)
      refuse("metric name '" + m.name + "' empty or repeated");
    check_finite(m.value, "metric " + m.name, path);
    check_finite(m.threshold, "the threshold of " + m.name, path);
  }
}

std::int64_t as_integer(std::uint64_t v) {
  return static_cast<std::int64_t>(v);
}
std::int64_t as_integer(bool v) {
  return v ? 1 : 0;
}

bool as_flag(const SqliteStatement& s, int column) {
  return s.integer_column(column) != 0;
}

}  // namespace

const char* to_string(HeartMode mode) {
  return mode == HeartMode::dynamic ? "dynamic" : "static";
}

const char* to_string(OperatorKind kind) {
  switch (kind) {
    case OperatorKind::human_device:
      return "human_device";
    case OperatorKind::script:
      return "script";
    case OperatorKind::scripted_operator:
      return "scripted_operator";
    case OperatorKind::replay:
      return "replay";
  }
  return "unknown";
}

std::optional<HeartMode> heart_mode_from(const std::string& text) {
  for (HeartMode m : {HeartMode::dynamic, HeartMode::static_heart})
    if (text == to_string(m)) return m;
  return std::nullopt;
}

std::optional<OperatorKind> operator_kind_from(const std::string& text) {
  for (OperatorKind k : {OperatorKind::human_device, OperatorKind::script,
                         OperatorKind::scripted_operator, OperatorKind::replay})
    if (text == to_string(k)) return k;
  return std::nullopt;
}

TraineeRecords::TraineeRecords(const std::string& path, Access access) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (access == Access::read_only && !fs::exists(path, ec))
    throw RecordsError(path + ": no trainee records here (no such file)");
  // /dev/null reads as an empty database and takes every write.
  if (fs::exists(path, ec) && !fs::is_regular_file(path, ec))
    throw RecordsError(path + ": not a regular file (the trainee records are a database file)");
  if (access == Access::append) {
    const fs::path parent = fs::path(path).parent_path();
    if (!parent.empty() && !fs::is_directory(parent, ec))
      throw RecordsError(path + ": cannot create the trainee records: the directory " +
                         parent.string() + " does not exist");
  }
  const int flags =
      access == Access::append ? SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE : SQLITE_OPEN_READONLY;
  db_ = std::make_unique<SqliteDatabase>(path, flags | SQLITE_OPEN_NOMUTEX, kRecordsBusyTimeoutMs);
  prepare_schema(access);
  if (access == Access::read_only) return;
  check_before_work();
  import_pending();
}

void TraineeRecords::prepare_schema(Access access) {
  SqliteDatabase& db = *db_;
  // The file's marks and its number of tables, read in one statement so that they are of one
  // moment (another process may be creating the schema). The first read of the file: a file
  // that is not SQLite fails here (SQLITE_NOTADB).
  struct Marks {
    std::int64_t application = 0, version = 0, tables = 0;
  };
  const auto read_marks = [&db] {
    const char* what = "reading the file's application id and schema version";
    SqliteStatement s = db.prepare(
        "SELECT (SELECT application_id FROM pragma_application_id), "
        "(SELECT user_version FROM pragma_user_version), (SELECT count(*) FROM sqlite_schema)",
        what);
    if (!s.step()) db.fail(what, SQLITE_CORRUPT);
    return Marks{s.integer_column(0), s.integer_column(1), s.integer_column(2)};
  };
  const auto check_marks = [&db](const Marks& marks) {
    const auto [application, version, tables] = marks;
    if (application == 0 && version == 0 && tables == 0) return false;  // new and empty
    if (application != kRecordsApplicationId)
      throw RecordsError(db.path() + ": an SQLite database of another program (application_id " +
                         std::to_string(application) + ", " + std::to_string(tables) +
                         " tables), not imasim's trainee records");
    if (version > kRecordsSchemaVersion)
      throw RecordsError(db.path() + ": trainee records of a newer imasim (schema version " +
                         std::to_string(version) + "; this one reads up to " +
                         std::to_string(kRecordsSchemaVersion) + ")");
    if (version < 1)
      throw RecordsError(db.path() + ": trainee records with no schema version (user_version " +
                         std::to_string(version) + ")");
    return true;
  };
  has_schema_ = check_marks(read_marks());
  if (access == Access::read_only) return;
  db.execute("PRAGMA foreign_keys=ON", "enabling foreign keys");
  use_write_ahead_log(db);
  if (has_schema_) return;
  // Two processes may find the file new at once: the second finds the schema inside its
  // transaction, written by the first.
  Transaction t(db);
  if (!check_marks(read_marks())) {
    db.execute(kSchema, "creating the schema");
    db.execute(("PRAGMA application_id=" + std::to_string(kRecordsApplicationId)).c_str(),
               "marking the file as imasim's");
    db.execute(("PRAGMA user_version=" + std::to_string(kRecordsSchemaVersion)).c_str(),
               "writing the schema version");
  }
  t.commit();
  has_schema_ = true;
}

std::int64_t TraineeRecords::append_session(const SessionRecord& s) {
  check_session(s, path());
  Transaction t(*db_);
  const std::int64_t id = insert_session(s);
  t.commit();
  return id;
}

std::int64_t TraineeRecords::insert_session(const SessionRecord& s) {
  SqliteDatabase& db = *db_;
  SqliteStatement session = db.prepare(
      "INSERT INTO sessions (trainee, date_utc, scene, heart, patient_seed, operator, input, "
      "status, recording, sai_radius_m) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9, ?10)",
      "appending a session");
  session.bind(1, s.trainee);
  session.bind(2, s.date_utc);
  session.bind(3, s.scene);
  session.bind(4, std::string_view(to_string(s.heart)));
  session.bind(5, as_integer(s.patient_seed));
  session.bind(6, std::string_view(to_string(s.operator_kind)));
  session.bind(7, s.input);
  session.bind(8, s.status);
  session.bind(9, s.recording);
  session.bind(10, s.sai_radius);
  session.step();
  const std::int64_t id = db.last_insert_rowid();

  SqliteStatement sai = db.prepare(
      "INSERT INTO session_sai (session_id, position, instrument, sai, samples, "
      "mean_distance_m, heart_side_fraction) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7)",
      "appending a session's SAI");
  for (std::size_t k = 0; k < s.sai.size(); ++k) {
    const InstrumentSai& i = s.sai[k];
    sai.bind(1, id);
    sai.bind(2, as_integer(std::uint64_t(k)));
    sai.bind(3, i.instrument);
    sai.bind(4, double(i.result.sai));
    sai.bind(5, as_integer(std::uint64_t(i.result.samples)));
    sai.bind(6, double(i.result.mean_distance));
    sai.bind(7, double(i.result.heart_side_fraction));
    sai.step();
    sai.reset();
  }
  SqliteStatement metric = db.prepare(
      "INSERT INTO session_metrics (session_id, position, name, unit, meaning, value, threshold, "
      "higher_is_better, pass) VALUES (?1, ?2, ?3, ?4, ?5, ?6, ?7, ?8, ?9)",
      "appending a session's metrics");
  for (std::size_t k = 0; k < s.metrics.size(); ++k) {
    const TraineeMetric& m = s.metrics[k];
    metric.bind(1, id);
    metric.bind(2, as_integer(std::uint64_t(k)));
    metric.bind(3, m.name);
    metric.bind(4, m.unit);
    metric.bind(5, m.meaning);
    metric.bind(6, m.value);
    metric.bind(7, m.threshold);
    metric.bind(8, as_integer(m.higher_is_better));
    metric.bind(9, as_integer(m.pass));
    metric.step();
    metric.reset();
  }
  return id;
}

AppendResult TraineeRecords::append_or_hold(const SessionRecord& s, int wait_ms) {
  check_session(s, path());
  db_->set_busy_timeout(wait_ms);
  try {
    const std::int64_t id = append_session(s);
    db_->set_busy_timeout(kRecordsBusyTimeoutMs);
    return {id, {}};
  } catch (const RecordsBusy&) {
    db_->set_busy_timeout(kRecordsBusyTimeoutMs);
  }
  // Beside the records, a file of its own, which no other process holds.
  static std::uint32_t held = 0;
  const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(
                      std::chrono::system_clock::now().time_since_epoch())
                      .count();
  const std::string pending = path() + kPendingInfix + std::to_string(ms) + "-" +
                              std::to_string(::getpid()) + "-" + std::to_string(held++) +
                              kPendingSuffix;
  TraineeRecords(pending, Access::append).append_session(s);
  return {0, pending};
}

void TraineeRecords::check_before_work() {
  SqliteDatabase& db = *db_;
  if (db.read_only())
    throw RecordsError(path() +
                       ": the trainee records cannot be written (a write-protected file or a "
                       "read-only file system)");
  {
    SqliteStatement check = db.prepare("PRAGMA quick_check", "checking the file (quick_check)");
    const std::string verdict = check.step() ? check.text_column(0) : std::string("no answer");
    if (verdict != "ok")
      throw RecordsError(path() + ": the trainee records are damaged (quick_check: " +
                         printable(verdict, 200) + ")");
  }
  // Writing: the write lock taken and given back. Another process's write is over in
  // milliseconds; a lock held longer is for the append at the end to wait for (or hold the
  // session pending), not a reason to refuse the session.
  db.set_busy_timeout(kRecordsCheckWaitMs);
  try {
    db.execute("BEGIN IMMEDIATE", "testing for writing");
    db.execute("ROLLBACK", "testing for writing");
  } catch (const RecordsBusy&) {
  }
  db.set_busy_timeout(kRecordsBusyTimeoutMs);
}

void TraineeRecords::import_pending() {
  namespace fs = std::filesystem;
  const fs::path self(path());
  const fs::path dir = self.has_parent_path() ? self.parent_path() : fs::path(".");
  const std::string prefix = self.filename().string() + kPendingInfix;
  std::vector<fs::path> files;
  std::error_code ec;
  for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() > prefix.size() + std::strlen(kPendingSuffix) && name.starts_with(prefix) &&
        name.ends_with(kPendingSuffix))
      files.push_back(it->path());
  }
  std::sort(files.begin(), files.end());
  for (const fs::path& file : files) {
    std::vector<SessionRecord> held;
    const std::string claimed = file.string() + ".claimed";
    try {
      // Under the records' write lock, so that two processes opening them at once take turns:
      // the second finds the file gone.
      Transaction t(*db_);
      if (!fs::exists(file, ec)) continue;
      held = TraineeRecords(file.string(), Access::read_only).sessions();
      for (const SessionRecord& s : held) {
        check_session(s, file.string());
        insert_session(s);
      }
      // Claimed before the commit, given back if it fails: never imported twice, never lost.
      fs::rename(file, claimed, ec);
      if (ec) throw RecordsError(file.string() + ": cannot claim it: " + ec.message());
      try {
        t.commit();
      } catch (const RecordsError&) {
        fs::rename(claimed, file, ec);
        throw;
      }
    } catch (const RecordsBusy&) {
      return;  // locked now: the next append-mode open tries again
    } catch (const RecordsError& e) {
      notes_.push_back(std::string("a held session file is left as it is: ") + e.what());
      continue;
    }
    for (const std::string& gone : {claimed, file.string() + "-wal", file.string() + "-shm"})
      fs::remove(gone, ec);
    ++imported_;
    notes_.push_back(std::to_string(held.size()) + " held session(s) from " + file.string() +
                     " added to the trainee records");
  }
}

std::vector<SessionRecord> TraineeRecords::sessions(const std::string& trainee) const {
  std::vector<SessionRecord> out;
  if (!has_schema_) return out;
  SqliteDatabase& db = *db_;
  SqliteStatement q = db.prepare(
      "SELECT id, trainee, date_utc, scene, heart, patient_seed, operator, input, status, "
      "recording, sai_radius_m FROM sessions WHERE ?1 = '' OR trainee = ?1 "
      "ORDER BY date_utc, id",
      "reading the sessions");
  q.bind(1, trainee);
  while (q.step()) {
    SessionRecord r;
    r.id = q.integer_column(0);
    r.trainee = q.text_column(1);
    r.date_utc = q.text_column(2);
    r.scene = q.text_column(3);
    const std::string heart = q.text_column(4);
    const std::optional<HeartMode> mode = heart_mode_from(heart);
    if (!mode)
      throw RecordsError(path() + ": session " + std::to_string(r.id) + ": unknown heart mode '" +
                         heart + "'");
    r.heart = *mode;
    r.patient_seed = static_cast<std::uint64_t>(q.integer_column(5));
    const std::string kind = q.text_column(6);
    const std::optional<OperatorKind> op = operator_kind_from(kind);
    if (!op)
      throw RecordsError(path() + ": session " + std::to_string(r.id) + ": unknown operator '" +
                         kind + "'");
    r.operator_kind = *op;
    r.input = q.text_column(7);
    r.status = q.text_column(8);
    r.recording = q.text_column(9);
    r.sai_radius = q.real_column(10);
    out.push_back(std::move(r));
  }
  SqliteStatement sai = db.prepare(
      "SELECT instrument, sai, samples, mean_distance_m, heart_side_fraction FROM session_sai "
      "WHERE session_id = ?1 ORDER BY position",
      "reading a session's SAI");
  SqliteStatement metric = db.prepare(
      "SELECT name, unit, meaning, value, threshold, higher_is_better, pass FROM "
      "session_metrics WHERE session_id = ?1 ORDER BY position",
      "reading a session's metrics");
  for (SessionRecord& r : out) {
    sai.bind(1, r.id);
    while (sai.step()) {
      InstrumentSai i;
      i.instrument = sai.text_column(0);
      i.result.sai = Real(sai.real_column(1));
      i.result.samples = static_cast<std::size_t>(sai.integer_column(2));
      i.result.mean_distance = Real(sai.real_column(3));
      i.result.heart_side_fraction = Real(sai.real_column(4));
      r.sai.push_back(std::move(i));
    }
    sai.reset();
    metric.bind(1, r.id);
    while (metric.step()) {
      TraineeMetric m;
      m.name = metric.text_column(0);
      m.unit = metric.text_column(1);
      m.meaning = metric.text_column(2);
      m.value = metric.real_column(3);
      m.threshold = metric.real_column(4);
      m.higher_is_better = as_flag(metric, 5);
      m.pass = as_flag(metric, 6);
      r.metrics.push_back(std::move(m));
    }
    metric.reset();
  }
  return out;
}

std::vector<std::string> TraineeRecords::trainees() const {
  std::vector<std::string> out;
  if (!has_schema_) return out;
  SqliteStatement q =
      db_->prepare("SELECT DISTINCT trainee FROM sessions ORDER BY trainee", "reading trainees");
  while (q.step())
    out.push_back(q.text_column(0));
  return out;
}

MetricHistory TraineeRecords::metric_history(const std::string& trainee,
                                             const std::string& metric) const {
  MetricHistory h;
  h.trainee = trainee;
  h.metric = metric;
  if (!has_schema_) return h;
  // The session number counts every session of the trainee, with the metric or not.
  SqliteStatement q = db_->prepare(
      "SELECT n, id, date_utc, value, threshold, pass, unit, higher_is_better FROM ("
      "SELECT row_number() OVER (ORDER BY date_utc, id) AS n, id, date_utc FROM sessions "
      "WHERE trainee = ?1) AS numbered JOIN session_metrics ON session_id = numbered.id "
      "WHERE name = ?2 ORDER BY n",
      "reading a metric's history");
  q.bind(1, trainee);
  q.bind(2, metric);
  while (q.step()) {
    HistoryPoint p;
    p.session_number = q.integer_column(0);
    p.session_id = q.integer_column(1);
    p.date_utc = q.text_column(2);
    p.value = q.real_column(3);
    p.threshold = q.real_column(4);
    p.pass = as_flag(q, 5);
    h.unit = q.text_column(6);
    h.higher_is_better = as_flag(q, 7);
    h.points.push_back(std::move(p));
  }
  return h;
}

std::string utc_timestamp() {
  const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  std::tm parts{};
  gmtime_r(&now, &parts);
  char text[32];
  const std::size_t n = std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &parts);
  return std::string(text, n);
}

std::string timestamp_problem(const std::string& text) {
  const std::string shape = "YYYY-MM-DDTHH:MM:SSZ";
  const std::string why = "'" + text + "' is no UTC time of the form " + shape;
  if (text.size() != shape.size()) return why;
  for (std::size_t i = 0; i < shape.size(); ++i) {
    const bool digit = text[i] >= '0' && text[i] <= '9';
    if (std::string_view("YMDHS").find(shape[i]) != std::string_view::npos ? !digit
                                                                           : text[i] != shape[i])
      return why;
  }
  const auto field = [&text](std::size_t at, std::size_t n) {
    return std::stoi(text.substr(at, n));
  };
  const int year = field(0, 4), month = field(5, 2), day = field(8, 2);
  const std::chrono::year_month_day date{std::chrono::year(year),
                                         std::chrono::month(unsigned(month)),
                                         std::chrono::day(unsigned(day))};
  if (!date.ok() || field(11, 2) > 23 || field(14, 2) > 59 || field(17, 2) > 60) return why;
  return {};
}

}  // namespace imasim::metrics
