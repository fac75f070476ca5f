// Trainee records in SQLite (metrics/trainee_records.hpp): a session reads back exactly, two
// processes appending at once lose nothing, files that are not ours are refused naming them,
// queries filter by trainee and order by date, and a metric's history is the progress plot's.
#include <gtest/gtest.h>
#include <sqlite3.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "metrics/records_path.hpp"
#include "metrics/sqlite_database.hpp"
#include "metrics/trainee_metrics.hpp"
#include "metrics/trainee_name.hpp"
#include "metrics/trainee_progress.hpp"
#include "metrics/trainee_records.hpp"

namespace {

using imasim::metrics::HeartMode;
using imasim::metrics::OperatorKind;
using imasim::metrics::RecordsError;
using imasim::metrics::SessionRecord;
using imasim::metrics::TraineeMetric;
using imasim::metrics::TraineeRecords;

namespace fs = std::filesystem;
constexpr auto kAppend = TraineeRecords::Access::append;
constexpr auto kRead = TraineeRecords::Access::read_only;

// A fresh path in the test's temporary directory (nothing left from an earlier run).
std::string fresh_path(const std::string& name) {
  const fs::path dir = fs::path(::testing::TempDir()) / "imasim_trainee_records";
  fs::create_directories(dir);
  const fs::path p = dir / name;
  // remove_all: a name used as a folder by an earlier run goes too (the test runs again).
  for (const char* suffix : {"", "-wal", "-shm", "-journal"})
    fs::remove_all(p.string() + suffix);
  return p.string();
}

// Every metric of trainee_metrics, with values that need all 64 bits of a double.
SessionRecord example_session(const std::string& trainee, const std::string& date, double salt) {
  SessionRecord s;
  s.trainee = trainee;
  s.date_utc = date;
  s.scene = "scenes/thorax_small.toml";
  s.heart = HeartMode::static_heart;
  s.patient_seed = 9'000'000'000'000'000'001u;
  s.operator_kind = OperatorKind::human_device;
  s.input = "openigtlink";
  s.status = "interrupted";
  s.recording = "/data/run 7.csv";
  s.sai_radius = 0.002;
  s.sai.push_back({"forceps", {imasim::Real(-11.018372910001 + salt), 61, 0.0172, 0.75}});
  s.sai.push_back({"hook", {imasim::Real(0.1 + 0.2), 60, 0.03, 1.0 / 3.0}});
  const std::vector<std::string> names = imasim::metrics::trainee_metric_names();
  for (std::size_t k = 0; k < names.size(); ++k) {
    TraineeMetric m;
    m.name = names[k];
    m.unit = std::string(k % 2 == 1 ? "m" : "1") + (k % 5 == 0 ? "/s" : "");
    m.meaning = "meaning of " + names[k] + ", with 'quotes' and \"more\"";
    m.value = std::nextafter(double(k) / 7 + salt, 1e9);
    m.threshold = k == 3 ? 1e-300 : double(k) * 0.1;
    m.higher_is_better = k % 3 == 0;
    m.pass = k % 4 != 1;
    s.metrics.push_back(m);
  }
  return s;
}

void expect_same(const SessionRecord& a, const SessionRecord& b) {
  EXPECT_EQ(a.trainee, b.trainee);
  EXPECT_EQ(a.date_utc, b.date_utc);
  EXPECT_EQ(a.scene, b.scene);
  EXPECT_EQ(a.heart, b.heart);
  EXPECT_EQ(a.patient_seed, b.patient_seed);
  EXPECT_EQ(a.operator_kind, b.operator_kind);
  EXPECT_EQ(a.input, b.input);
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.recording, b.recording);
  EXPECT_EQ(a.sai_radius, b.sai_radius);
  ASSERT_EQ(a.sai.size(), b.sai.size());
  for (std::size_t k = 0; k < a.sai.size(); ++k) {
    EXPECT_EQ(a.sai[k].instrument, b.sai[k].instrument);
    EXPECT_EQ(a.sai[k].result.sai, b.sai[k].result.sai);  // bit for bit
    EXPECT_EQ(a.sai[k].result.samples, b.sai[k].result.samples);
    EXPECT_EQ(a.sai[k].result.mean_distance, b.sai[k].result.mean_distance);
    EXPECT_EQ(a.sai[k].result.heart_side_fraction, b.sai[k].result.heart_side_fraction);
  }
  ASSERT_EQ(a.metrics.size(), b.metrics.size());
  for (std::size_t k = 0; k < a.metrics.size(); ++k) {
    SCOPED_TRACE(a.metrics[k].name);
    EXPECT_EQ(a.metrics[k].name, b.metrics[k].name);
    EXPECT_EQ(a.metrics[k].unit, b.metrics[k].unit);
    EXPECT_EQ(a.metrics[k].meaning, b.metrics[k].meaning);
    EXPECT_EQ(a.metrics[k].value, b.metrics[k].value);
    EXPECT_EQ(a.metrics[k].threshold, b.metrics[k].threshold);
    EXPECT_EQ(a.metrics[k].higher_is_better, b.metrics[k].higher_is_better);
    EXPECT_EQ(a.metrics[k].pass, b.metrics[k].pass);
  }
}

std::string message_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const RecordsError& e) {
    return e.what();
  }
  return "(no error)";
}

// Runs `work(k)` in two child processes started together (k = 0, 1) and expects both to exit 0;
// a child that throws says why on stderr.
void in_two_processes_at_once(const std::function<void(int)>& work) {
  int go[2];
  ASSERT_EQ(pipe(go), 0);
  std::vector<pid_t> children;
  for (int k = 0; k < 2; ++k) {
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      close(go[1]);
      char byte = 0;
      (void)!read(go[0], &byte, 1);  // both start together: the parent closes the pipe
      try {
        work(k);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "child %d: %s\n", k, e.what());
        _exit(1);
      }
      _exit(0);
    }
    children.push_back(pid);
  }
  close(go[0]);
  close(go[1]);
  for (const pid_t pid : children) {
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
  }
}

TEST(TraineeRecords, ASessionReadsBackExactlyWithItsMetricsInOrder) {
  const std::string path = fresh_path("exact.sqlite");
  const SessionRecord written = example_session("José Álvarez", "2025-03-01T14:05:09Z", 0);
  std::int64_t id = 0;
  {
    TraineeRecords records(path, kAppend);
    id = records.append_session(written);
    EXPECT_GT(id, 0);
  }
  const TraineeRecords again(path, kRead);  // another connection: it is on disk
  const std::vector<SessionRecord> read = again.sessions();
  ASSERT_EQ(read.size(), 1u);
  EXPECT_EQ(read[0].id, id);
  EXPECT_GE(read[0].metrics.size(), 15u);
  expect_same(read[0], written);
  EXPECT_EQ(again.trainees(), std::vector<std::string>{"José Álvarez"});
}

TEST(TraineeRecords, TwoProcessesAppendingAtOnceLoseNoSession) {
  const std::string path = fresh_path("concurrent.sqlite");
  constexpr int kEach = 50;
  in_two_processes_at_once([&](int k) {
    // Both create the database at once, then append.
    const char* trainee = k == 0 ? "first" : "second";
    TraineeRecords records(path, kAppend);
    for (int n = 0; n < kEach; ++n)
      records.append_session(example_session(trainee, "2025-03-01T14:05:09Z", n));
  });
  const TraineeRecords records(path, kRead);
  EXPECT_EQ(records.sessions().size(), 2u * kEach);
  for (const char* trainee : {"first", "second"}) {
    const std::vector<SessionRecord> mine = records.sessions(trainee);
    ASSERT_EQ(mine.size(), std::size_t(kEach)) << trainee;
    for (int k = 0; k < kEach; ++k)  // same date: in the order each appended them
      expect_same(mine[std::size_t(k)], example_session(trainee, "2025-03-01T14:05:09Z", k));
  }
}

TEST(TraineeRecords, AFileThatIsNotSqliteIsRefusedNamingIt) {
  const std::string path = fresh_path("notes.sqlite");
  const std::string text(2000, 'x');
  { std::ofstream(path) << text; }
  for (const auto access : {kAppend, kRead}) {
    const std::string m = message_of([&] { TraineeRecords r(path, access); });
    EXPECT_NE(m.find(path + ": is not an SQLite database"), std::string::npos) << m;
  }
  std::ifstream in(path);
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(in), {}), text);  // untouched
}

// A damaged file passed the check at the start and failed only at the end, after the session
// had been spent ("database disk image is malformed", exit 4). It is refused on opening now.
TEST(TraineeRecords, ADamagedFileIsRefusedBeforeTheSession) {
  const std::string path = fresh_path("damaged.sqlite");
  {
    TraineeRecords r(path, kAppend);
    for (int k = 0; k < 20; ++k)
      r.append_session(example_session("a", "2025-03-01T14:05:09Z", k));
  }
  const auto pages = fs::file_size(path) / 4096;
  ASSERT_GE(pages, 4u);
  {  // the pages after the first two overwritten; the header stays readable
    std::fstream f(path, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(2 * 4096);
    const std::string garbage((pages - 2) * 4096, char(0xa5));
    f.write(garbage.data(), std::streamsize(garbage.size()));
  }
  const std::string m = message_of([&] { TraineeRecords r(path, kAppend); });
  EXPECT_EQ(m.rfind(path + ": ", 0), 0u) << m;
  EXPECT_TRUE(m.find("damaged") != std::string::npos || m.find("malformed") != std::string::npos)
      << m;
}

// /dev/null read as an empty database, and took every write.
TEST(TraineeRecords, ADeviceIsNotADatabaseFile) {
  for (const auto access : {kAppend, kRead}) {
    const std::string m = message_of([&] { TraineeRecords r("/dev/null", access); });
    EXPECT_EQ(m, "/dev/null: not a regular file (the trainee records are a database file)");
  }
}

// Another process holding the write lock made the append at a session's end wait 30 s and then
// lose the session. It waits a bounded time, then holds the session in a file of its own beside
// the records, which the next opening for append adds (and removes).
TEST(TraineeRecords, ALockedDatabaseHoldsTheSessionPendingAndTheNextOpeningAddsIt) {
  const std::string path = fresh_path("locked.sqlite");
  const SessionRecord session = example_session("b", "2025-03-02T09:00:00Z", 1);
  std::string pending;
  {
    TraineeRecords records(path, kAppend);
    imasim::metrics::SqliteDatabase other(path, SQLITE_OPEN_READWRITE, 1000);
    other.execute("BEGIN IMMEDIATE", "another process's write");
    const imasim::metrics::AppendResult r = records.append_or_hold(session, 200);
    EXPECT_EQ(r.id, 0);
    pending = r.pending;
    ASSERT_EQ(pending.rfind(path + ".pending-", 0), 0u) << pending;
    EXPECT_TRUE(fs::exists(pending));
    other.execute("ROLLBACK", "another process's write");
    EXPECT_TRUE(TraineeRecords(path, kRead).sessions().empty());  // not in yet
  }
  const TraineeRecords next(path, kAppend);
  EXPECT_EQ(next.imported_pending(), 1u);
  ASSERT_EQ(next.notes().size(), 1u);
  EXPECT_NE(next.notes()[0].find("1 held session(s) from " + pending), std::string::npos);
  EXPECT_FALSE(fs::exists(pending));
  const std::vector<SessionRecord> read = next.sessions();
  ASSERT_EQ(read.size(), 1u);
  expect_same(read[0], session);
  // Unlocked, the session goes straight in.
  TraineeRecords records(path, kAppend);
  const imasim::metrics::AppendResult r = records.append_or_hold(session, 200);
  EXPECT_GT(r.id, 0);
  EXPECT_TRUE(r.pending.empty());
}

// A study's trials open the records at once: a held session is added by one of them, once.
TEST(TraineeRecords, TwoProcessesOpeningAtOnceAddAHeldSessionOnce) {
  const std::string path = fresh_path("held_once.sqlite");
  {
    TraineeRecords records(path, kAppend);
    imasim::metrics::SqliteDatabase other(path, SQLITE_OPEN_READWRITE, 1000);
    other.execute("BEGIN IMMEDIATE", "another process's write");
    ASSERT_FALSE(records.append_or_hold(example_session("c", "2025-03-03T10:00:00Z", 2), 100)
                     .pending.empty());
    other.execute("ROLLBACK", "another process's write");
  }
  for (int round = 0; round < 2; ++round)
    in_two_processes_at_once([&](int) { TraineeRecords records(path, kAppend); });
  EXPECT_EQ(TraineeRecords(path, kRead).sessions().size(), 1u);
  for (const auto& entry : fs::directory_iterator(fs::path(path).parent_path()))
    EXPECT_EQ(entry.path().filename().string().find("held_once.sqlite.pending-"), std::string::npos)
        << entry.path();
}

TEST(TraineeRecords, ANewerSchemaOrAnotherProgramsDatabaseIsRefused) {
  const std::string newer = fresh_path("newer.sqlite");
  {
    TraineeRecords r(newer, kAppend);  // ours, then marked as from a later version
    imasim::metrics::SqliteDatabase raw(newer, SQLITE_OPEN_READWRITE, 1000);
    raw.execute("PRAGMA user_version=2", "test");
  }
  for (const auto access : {kAppend, kRead}) {
    const std::string m = message_of([&] { TraineeRecords r(newer, access); });
    EXPECT_NE(m.find(newer + ": trainee records of a newer imasim (schema version 2; this one "
                             "reads up to 1)"),
              std::string::npos)
        << m;
  }
  const std::string foreign = fresh_path("foreign.sqlite");
  {
    imasim::metrics::SqliteDatabase raw(foreign, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, 1000);
    raw.execute("CREATE TABLE patients (name TEXT)", "test");
  }
  const std::string m = message_of([&] { TraineeRecords r(foreign, kAppend); });
  EXPECT_NE(m.find(foreign + ": an SQLite database of another program"), std::string::npos) << m;
}

TEST(TraineeRecords, AMissingFileOrDirectoryIsNamed) {
  const std::string missing = fresh_path("missing.sqlite");
  EXPECT_NE(message_of([&] { TraineeRecords r(missing, kRead); }).find(missing + ": no trainee"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(missing));  // reading creates nothing
  const std::string nowhere = fresh_path("no_such_dir") + "/records.sqlite";
  const std::string m = message_of([&] { TraineeRecords r(nowhere, kAppend); });
  EXPECT_NE(m.find("no_such_dir does not exist"), std::string::npos) << m;
  // A database created but never appended to reads as empty.
  const std::string empty = fresh_path("empty.sqlite");
  { TraineeRecords r(empty, kAppend); }
  const TraineeRecords r(empty, kRead);
  EXPECT_TRUE(r.sessions().empty());
  EXPECT_TRUE(r.trainees().empty());
}

TEST(TraineeRecords, BadSessionsAreRefusedAndLeaveNothing) {
  const std::string path = fresh_path("refused.sqlite");
  TraineeRecords records(path, kAppend);
  const auto refused = [&](SessionRecord s, const std::string& expected) {
    const std::string m = message_of([&] { records.append_session(s); });
    EXPECT_NE(m.find(path + ": cannot record"), std::string::npos) << m;
    EXPECT_NE(m.find(expected), std::string::npos) << m;
  };
  const SessionRecord good = example_session("ana", "2025-03-01T14:05:09Z", 0);
  SessionRecord s = good;
  s.trainee = "ana\x1b[31m";
  refused(s, "control character at byte 4");
  s.trainee = std::string(65, 'a');
  refused(s, "65 characters, above the limit of 64");
  s = good;
  s.date_utc = "2025-02-30T10:00:00Z";
  refused(s, "'2025-02-30T10:00:00Z' is no UTC time");
  s = good;
  s.metrics[2].value = std::numeric_limits<double>::quiet_NaN();
  refused(s, "metric " + good.metrics[2].name);
  s = good;
  s.metrics.push_back(good.metrics[0]);
  refused(s, "'" + good.metrics[0].name + "' empty or repeated");
  s = good;
  s.patient_seed = std::numeric_limits<std::uint64_t>::max();
  refused(s, "above 2^63 - 1");
  EXPECT_TRUE(records.sessions().empty());
}

TEST(TraineeRecords, SessionsFilterByTraineeAndComeInDateOrder) {
  const std::string path = fresh_path("order.sqlite");
  TraineeRecords records(path, kAppend);
  const std::int64_t late =
      records.append_session(example_session("ana", "2025-03-02T09:00:00Z", 0));
  const std::int64_t bob =
      records.append_session(example_session("bob", "2025-03-01T12:00:00Z", 1));
  const std::int64_t early =
      records.append_session(example_session("ana", "2025-03-01T08:00:00Z", 2));
  const std::vector<SessionRecord> ana = records.sessions("ana");
  ASSERT_EQ(ana.size(), 2u);
  EXPECT_EQ(ana[0].id, early);
  EXPECT_EQ(ana[1].id, late);
  const std::vector<SessionRecord> all = records.sessions();
  ASSERT_EQ(all.size(), 3u);
  EXPECT_EQ(all[0].id, early);
  EXPECT_EQ(all[1].id, bob);
  EXPECT_EQ(all[2].id, late);
  EXPECT_TRUE(records.sessions("carol").empty());
  EXPECT_EQ(records.trainees(), (std::vector<std::string>{"ana", "bob"}));
}

TEST(TraineeRecords, AMetricsHistoryNumbersTheTraineesSessions) {
  const std::string path = fresh_path("history.sqlite");
  TraineeRecords records(path, kAppend);
  const auto with_contacts = [](const std::string& trainee, const std::string& date,
                                double contacts) {
    SessionRecord s = example_session(trainee, date, 0);
    for (TraineeMetric& m : s.metrics) {
      if (m.name != "heart_contacts") continue;
      m.value = contacts;
      m.threshold = 0;
      m.higher_is_better = false;
      m.pass = contacts <= 0;
    }
    return s;
  };
  records.append_session(with_contacts("ana", "2025-03-03T10:00:00Z", 0));
  records.append_session(with_contacts("ana", "2025-03-01T10:00:00Z", 25));
  records.append_session(with_contacts("bob", "2025-03-02T10:00:00Z", 7));
  SessionRecord without = with_contacts("ana", "2025-03-02T10:00:00Z", 0);
  without.metrics.clear();  // numbered, but no point of the series
  records.append_session(without);

  const imasim::metrics::MetricHistory h = records.metric_history("ana", "heart_contacts");
  for (const TraineeMetric& m : example_session("x", "2025-03-01T10:00:00Z", 0).metrics)
    if (m.name == "heart_contacts") {
      EXPECT_EQ(h.unit, m.unit);
    }
  EXPECT_FALSE(h.higher_is_better);
  ASSERT_EQ(h.points.size(), 2u);
  EXPECT_EQ(h.points[0].session_number, 1);
  EXPECT_EQ(h.points[0].date_utc, "2025-03-01T10:00:00Z");
  EXPECT_EQ(h.points[0].value, 25);
  EXPECT_FALSE(h.points[0].pass);
  EXPECT_EQ(h.points[1].session_number, 3);
  EXPECT_EQ(h.points[1].value, 0);
  EXPECT_EQ(h.points[1].threshold, 0);
  EXPECT_TRUE(h.points[1].pass);
  EXPECT_TRUE(records.metric_history("ana", "no_such_metric").points.empty());
}

TEST(TraineeProgress, FirstAgainstLatestAndTheLeastSquaresTrend) {
  std::vector<SessionRecord> sessions;
  for (const std::size_t passed : {9u, 15u, 12u}) {  // shares 1/2, 5/6, 2/3
    SessionRecord s = example_session("ana", "2025-03-01T10:00:00Z", 0);
    s.metrics.resize(18);
    for (std::size_t k = 0; k < 18; ++k)
      s.metrics[k].pass = k < passed;
    s.metrics[0].name = "time_to_complete_s";
    s.metrics[0].value = 100.0 + double(passed);
    sessions.push_back(s);
  }
  const imasim::metrics::TraineeProgress p = imasim::metrics::trainee_progress(sessions);
  EXPECT_EQ(p.sessions, 3u);
  EXPECT_EQ(p.first.passed, 9u);
  EXPECT_EQ(p.latest.passed, 12u);
  EXPECT_EQ(p.latest.total, 18u);
  // x = 1, 2, 3 (mean 2), y = 1/2, 5/6, 2/3: slope = (-1 * 1/2 + 1 * 2/3) / 2 = 1/12.
  EXPECT_NEAR(p.passed_share_trend, 1.0 / 12.0, 1e-15);
  EXPECT_EQ(p.first_time_to_complete_s, 109.0);
  EXPECT_EQ(p.latest_time_to_complete_s, 112.0);
  EXPECT_EQ(imasim::metrics::trainee_progress(std::span(sessions).first(1)).passed_share_trend,
            0.0);
}

TEST(TraineeName, PrintableTextOfAtMost64Characters) {
  using imasim::metrics::trainee_name_problem;
  EXPECT_EQ(trainee_name_problem("José Álvarez"), "");
  EXPECT_EQ(trainee_name_problem(std::string(64, 'a')), "");
  EXPECT_EQ(trainee_name_problem("é" + std::string(63, 'a')), "");  // 65 bytes, 64 characters
  EXPECT_EQ(trainee_name_problem(std::string(65, 'a')), "has 65 characters, above the limit of 64");
  EXPECT_EQ(trainee_name_problem(""), "is empty");
  EXPECT_EQ(trainee_name_problem(" ana"), "begins or ends with a space");
  EXPECT_NE(trainee_name_problem("ana\tb").find("control character at byte 4"), std::string::npos);
  EXPECT_NE(trainee_name_problem("a\xC2\x85"), "");  // U+0085, a C1 control
  EXPECT_NE(trainee_name_problem("Jos\xC3").find("not valid UTF-8 (at byte 4)"), std::string::npos);
  EXPECT_NE(trainee_name_problem("\xC0\xAF"), "");      // an overlong '/'
  EXPECT_NE(trainee_name_problem("\xED\xA0\x80"), "");  // a surrogate
}

TEST(RecordsPath, TheUsersDataDirectoryAfterTheXdgSpecification) {
  using imasim::metrics::records_path_from;
  EXPECT_EQ(records_path_from("/data/x", "/home/ana"), "/data/x/imasim/trainees.sqlite");
  EXPECT_EQ(records_path_from(nullptr, "/home/ana"),
            "/home/ana/.local/share/imasim/trainees.sqlite");
  EXPECT_EQ(records_path_from("relative/dir", "/home/ana"),  // not absolute: ignored
            "/home/ana/.local/share/imasim/trainees.sqlite");
  EXPECT_THROW(records_path_from(nullptr, nullptr), RecordsError);
  EXPECT_THROW(records_path_from("", ""), RecordsError);

  const std::string root = fresh_path("data_home");
  fs::remove_all(root);
  const std::string db = records_path_from(root.c_str(), nullptr);
  imasim::metrics::create_records_directory(db);
  EXPECT_TRUE(fs::is_directory(root + "/imasim"));
  { TraineeRecords r(db, kAppend); }
  EXPECT_TRUE(fs::exists(db));
  // A file where a directory should be: refused naming the directory.
  const std::string blocked = fresh_path("blocked");
  { std::ofstream(blocked) << "a file"; }
  const std::string m =
      message_of([&] { imasim::metrics::create_records_directory(blocked + "/imasim/x.sqlite"); });
  EXPECT_NE(m.find("cannot create the directory " + blocked + "/imasim"), std::string::npos) << m;
}

TEST(RecordsPath, UtcTimestampsAreIso8601ToTheSecond) {
  using imasim::metrics::timestamp_problem;
  EXPECT_EQ(timestamp_problem(imasim::metrics::utc_timestamp()), "");
  EXPECT_EQ(timestamp_problem("2024-02-29T23:59:59Z"), "");
  EXPECT_NE(timestamp_problem("2023-02-29T23:59:59Z"), "");  // no leap year
  EXPECT_NE(timestamp_problem("2024-02-28 23:59:59Z"), "");
  EXPECT_NE(timestamp_problem("2024-02-28T24:00:00Z"), "");
  EXPECT_NE(timestamp_problem("2024-02-28T23:59:59"), "");
}

}  // namespace
