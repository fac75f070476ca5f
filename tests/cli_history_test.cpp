// Trainee records from the command line: `imasim run --record` appends its scored session to the
// database (--db, or the user's data directory), and `imasim history` shows it back as a table or
// as JSON with exactly the documented keys. Every run here names its own database or data
// directory under the test's temporary folder: the real user's records are never touched.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_process.hpp"

namespace {

using imasim::test::Finished;
using imasim::test::read_file;
namespace fs = std::filesystem;

const std::string kDir = ::testing::TempDir() + "imasim_history/";
std::string err_file() {
  return imasim::test::test_err_file(::testing::TempDir(), "imasim_history");
}
const std::string kScript = IMASIM_SOURCE_DIR "/examples/open_fascia.script";

// `env` first: the variables a test sets (XDG_DATA_HOME, USER) and none of the user's data home.
Finished run(const std::string& args, const std::string& env = "") {
  return imasim::test::run_imasim(args, err_file(),
                                  "env XDG_DATA_HOME=" + kDir + "unused_data_home " + env);
}

std::string fresh(const std::string& name) {
  fs::create_directories(kDir);
  const std::string p = kDir + name;
  fs::remove_all(p);
  for (const char* suffix : {"-wal", "-shm", "-journal"})
    fs::remove(p + suffix);
  return p;
}

std::vector<std::string> keys_of(const nlohmann::ordered_json& j) {
  std::vector<std::string> k;
  for (auto it = j.begin(); it != j.end(); ++it)
    k.push_back(it.key());
  return k;
}

Finished recorded_run(const std::string& csv, const std::string& extra,
                      const std::string& env = "") {
  return run("run --headless --script " + kScript + " --threads 1 --record " + csv + " " + extra +
                 " --json",
             env);
}

TEST(CliHistory, ARecordedRunLandsInTheDatabaseWithItsMetrics) {
  const std::string db = fresh("one.sqlite");
  const std::string csv = fresh("one.csv");
  const Finished f = recorded_run(csv, "--seconds 1 --db " + db + " --trainee alice");
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const nlohmann::ordered_json report = nlohmann::ordered_json::parse(f.out);
  const nlohmann::ordered_json note = report["trainee_record"];
  EXPECT_EQ(note["database"], db);
  EXPECT_EQ(note["session_id"], 1);
  EXPECT_EQ(note["trainee"], "alice");
  const nlohmann::ordered_json side = nlohmann::ordered_json::parse(read_file(kDir + "one.json"));
  EXPECT_EQ(side["run"]["trainee_record"], note);

  const Finished h = run("history --db " + db + " --json");
  ASSERT_EQ(h.exit_code, 0) << h.err;
  const nlohmann::ordered_json history = nlohmann::ordered_json::parse(h.out);
  ASSERT_EQ(history["trainees"].size(), 1u);
  const nlohmann::ordered_json& alice = history["trainees"][0];
  EXPECT_EQ(alice["trainee"], "alice");
  ASSERT_EQ(alice["sessions"].size(), 1u);
  const nlohmann::ordered_json& s = alice["sessions"][0];
  EXPECT_EQ(s["id"], 1);
  EXPECT_EQ(s["number"], 1);
  EXPECT_EQ(s["scene"], "built-in thorax");
  EXPECT_EQ(s["heart"], "dynamic");
  EXPECT_EQ(s["patient_seed"], report["patient_seed"]);
  EXPECT_EQ(s["operator"], "script");
  EXPECT_EQ(s["input"], "script");
  EXPECT_EQ(s["status"], "ok");
  EXPECT_EQ(s["recording"], fs::absolute(csv).string());
  // Every metric and both SAIs exactly as the run scored them (doubles read back bit for bit).
  EXPECT_EQ(s["metrics"], report["scores"]["metrics"]);
  EXPECT_EQ(s["sai"], report["scores"]["sai"]);
  EXPECT_EQ(s["metrics_passed"], report["scores"]["metrics_passed"]);
  EXPECT_EQ(s["metrics_total"], report["scores"]["metrics_total"]);
  EXPECT_NEAR(s["time_to_complete_s"].get<double>(), 1.0, 1e-9);

  const Finished text = run("history --db " + db);
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("alice: 1 session\n"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("SAI forceps"), std::string::npos) << text.out;
  EXPECT_NE(
      text.out.find("progress: one session, " + std::to_string(s["metrics_passed"].get<int>()) +
                    "/" + std::to_string(s["metrics_total"].get<int>()) + " ("),
      std::string::npos)
      << text.out;
}

TEST(CliHistory, TheJsonKeysPerTraineeInDateOrderWithAMetricsSeries) {
  const std::string db = fresh("three.sqlite");
  ASSERT_EQ(recorded_run(fresh("a1.csv"), "--seconds 0.6 --db " + db + " --trainee ana").exit_code,
            0);
  ASSERT_EQ(recorded_run(fresh("b1.csv"), "--seconds 0.2 --db " + db + " --trainee bob").exit_code,
            0);
  ASSERT_EQ(recorded_run(fresh("a2.csv"), "--seconds 0.2 --static --db " + db + " --trainee ana")
                .exit_code,
            0);
  const Finished h = run("history --db " + db + " --trainee ana --metric cautery_on_s --json");
  ASSERT_EQ(h.exit_code, 0) << h.err;
  const nlohmann::ordered_json r = nlohmann::ordered_json::parse(h.out);
  EXPECT_EQ(keys_of(r), (std::vector<std::string>{"database", "metric", "trainees"}));
  EXPECT_EQ(r["metric"], "cautery_on_s");
  ASSERT_EQ(r["trainees"].size(), 1u);  // bob filtered out
  const nlohmann::ordered_json& ana = r["trainees"][0];
  EXPECT_EQ(keys_of(ana), (std::vector<std::string>{"trainee", "sessions", "progress", "series"}));
  ASSERT_EQ(ana["sessions"].size(), 2u);
  EXPECT_EQ(
      keys_of(ana["sessions"][0]),
      (std::vector<std::string>{"number", "id", "date_utc", "scene", "heart", "patient_seed",
                                "operator", "input", "status", "recording", "sai", "metrics_passed",
                                "metrics_total", "time_to_complete_s", "metrics"}));
  EXPECT_EQ(keys_of(ana["sessions"][0]["sai"]),
            (std::vector<std::string>{"radius_m", "forceps", "hook"}));
  EXPECT_EQ(ana["sessions"][0]["heart"], "dynamic");  // the earlier session first
  EXPECT_EQ(ana["sessions"][1]["heart"], "static");
  EXPECT_EQ(ana["sessions"][1]["id"], 3);
  EXPECT_LE(ana["sessions"][0]["date_utc"].get<std::string>(),
            ana["sessions"][1]["date_utc"].get<std::string>());
  EXPECT_EQ(keys_of(ana["progress"]),
            (std::vector<std::string>{"sessions", "first_passed", "first_total",
                                      "first_passed_share", "latest_passed", "latest_total",
                                      "latest_passed_share", "passed_share_trend_per_session",
                                      "first_time_to_complete_s", "latest_time_to_complete_s"}));
  EXPECT_EQ(ana["progress"]["sessions"], 2);
  EXPECT_NEAR(ana["progress"]["first_time_to_complete_s"].get<double>(), 0.6, 1e-9);
  EXPECT_NEAR(ana["progress"]["latest_time_to_complete_s"].get<double>(), 0.2, 1e-9);
  const nlohmann::ordered_json& series = ana["series"];
  EXPECT_EQ(keys_of(series), (std::vector<std::string>{"metric", "unit", "better", "points"}));
  EXPECT_EQ(series["unit"], "s");
  EXPECT_EQ(series["better"], "lower");
  ASSERT_EQ(series["points"].size(), 2u);
  EXPECT_EQ(
      keys_of(series["points"][0]),
      (std::vector<std::string>{"number", "session_id", "date_utc", "value", "threshold", "pass"}));
  EXPECT_EQ(series["points"][0]["number"], 1);
  EXPECT_EQ(series["points"][1]["number"], 2);
  // The pedal is pressed from 0.5 s: 0.1 s of the first session, none of the second.
  EXPECT_NEAR(series["points"][0]["value"].get<double>(), 0.1, 0.02);
  EXPECT_EQ(series["points"][1]["value"], 0.0);

  const Finished all = run("history --db " + db + " --json");
  ASSERT_EQ(all.exit_code, 0) << all.err;
  const nlohmann::ordered_json everyone = nlohmann::ordered_json::parse(all.out);
  EXPECT_EQ(keys_of(everyone), (std::vector<std::string>{"database", "trainees"}));
  ASSERT_EQ(everyone["trainees"].size(), 2u);
  EXPECT_EQ(everyone["trainees"][0]["trainee"], "ana");
  EXPECT_EQ(everyone["trainees"][1]["trainee"], "bob");
  EXPECT_FALSE(everyone["trainees"][0].contains("series"));

  const Finished text = run("history --db " + db + " --trainee ana --metric cautery_on_s");
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("ana: 2 sessions\n"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("in session 2; trend"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("cautery_on_s (unit s, lower is better):"), std::string::npos)
      << text.out;
  EXPECT_EQ(text.out.find("bob"), std::string::npos) << text.out;
}

TEST(CliHistory, TheDefaultDatabaseAndTraineeComeFromTheEnvironment) {
  const std::string home = fresh("data_home");
  const Finished f =
      recorded_run(fresh("default.csv"), "--seconds 0.1", "XDG_DATA_HOME=" + home + " USER=carol");
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const std::string db = home + "/imasim/trainees.sqlite";
  EXPECT_EQ(nlohmann::json::parse(f.out)["trainee_record"]["database"], db);
  EXPECT_EQ(nlohmann::json::parse(f.out)["trainee_record"]["trainee"], "carol");
  const Finished h = run("history --json", "XDG_DATA_HOME=" + home);
  ASSERT_EQ(h.exit_code, 0) << h.err;
  EXPECT_EQ(nlohmann::json::parse(h.out)["trainees"][0]["trainee"], "carol");

  // --no-db: nothing appended, no database created.
  const std::string elsewhere = fresh("data_home_unused");
  const Finished none =
      recorded_run(fresh("none.csv"), "--seconds 0.1 --no-db", "XDG_DATA_HOME=" + elsewhere);
  ASSERT_EQ(none.exit_code, 0) << none.err;
  EXPECT_FALSE(nlohmann::json::parse(none.out).contains("trainee_record"));
  EXPECT_FALSE(fs::exists(elsewhere));
}

TEST(CliHistory, BadRequestsAreRefusedWithAClearMessage) {
  const std::string missing = fresh("missing.sqlite");
  const Finished m = run("history --db " + missing);
  EXPECT_EQ(m.exit_code, 2);
  EXPECT_NE(m.err.find("no trainee records at " + missing), std::string::npos) << m.err;

  const std::string notes = fresh("notes.sqlite");
  { std::ofstream(notes) << std::string(1000, 'n'); }
  const Finished bad = run("history --db " + notes);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find(notes + ": is not an SQLite database"), std::string::npos) << bad.err;
  // A run refuses it before simulating anything.
  const Finished run_bad = recorded_run(fresh("bad.csv"), "--seconds 0.1 --db " + notes);
  EXPECT_EQ(run_bad.exit_code, 2);
  EXPECT_NE(run_bad.err.find(notes + ": is not an SQLite database"), std::string::npos)
      << run_bad.err;
  EXPECT_TRUE(run_bad.out.empty()) << run_bad.out;

  const std::string db = fresh("bad_requests.sqlite");
  ASSERT_EQ(recorded_run(fresh("br.csv"), "--seconds 0.1 --db " + db + " --trainee dana").exit_code,
            0);
  const Finished who = run("history --db " + db + " --trainee dan");
  EXPECT_EQ(who.exit_code, 2);
  EXPECT_NE(who.err.find("no sessions of trainee 'dan' in " + db + " (trainees: dana)"),
            std::string::npos)
      << who.err;
  const Finished what = run("history --db " + db + " --metric heart_contact");
  EXPECT_EQ(what.exit_code, 2);
  EXPECT_NE(what.err.find("'heart_contact' is no metric; did you mean 'heart_contacts'?"),
            std::string::npos)
      << what.err;

  const Finished name = run("run --headless --script " + kScript + " --record " + fresh("n.csv") +
                            " --trainee \"$(printf 'eve\\033[2J')\"");
  EXPECT_NE(name.exit_code, 0);
  EXPECT_NE(name.err.find("control character at byte 4"), std::string::npos) << name.err;
  const Finished alone = run("run --headless --script " + kScript + " --seconds 0.1 --db " + db);
  EXPECT_EQ(alone.exit_code, 2);
  EXPECT_NE(alone.err.find("--trainee, --db and --no-db go with --record"), std::string::npos)
      << alone.err;
  const Finished both = recorded_run(fresh("both.csv"), "--seconds 0.1 --no-db --db " + db);
  EXPECT_NE(both.exit_code, 0);
  EXPECT_NE(both.err.find("--db excludes --no-db"), std::string::npos) << both.err;
}

// Records that cannot take a session are refused before it is spent: a damaged file (it failed
// only at the end, exit 4) and a device (/dev/null read as empty and took every write).
TEST(CliHistory, DamagedRecordsAndDevicesAreRefusedBeforeTheSession) {
  const std::string db = fresh("damaged.sqlite");
  ASSERT_EQ(recorded_run(fresh("d1.csv"), "--seconds 0.1 --db " + db + " --trainee dana").exit_code,
            0);
  const auto bytes = fs::file_size(db);
  ASSERT_GE(bytes, 3u * 4096u);
  {
    std::fstream f(db, std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(2 * 4096);
    const std::string garbage(bytes - 2 * 4096, char(0xa5));
    f.write(garbage.data(), std::streamsize(garbage.size()));
  }
  const std::string csv = fresh("d2.csv");
  const Finished damaged = recorded_run(csv, "--seconds 0.5 --db " + db + " --trainee dana");
  EXPECT_EQ(damaged.exit_code, 2);
  EXPECT_NE(damaged.err.find(db + ": the trainee records are damaged (quick_check: "),
            std::string::npos)
      << damaged.err;
  EXPECT_TRUE(damaged.out.empty()) << damaged.out;
  EXPECT_FALSE(fs::exists(csv));  // nothing simulated, nothing recorded
  for (const std::string& command :
       {std::string("history --db /dev/null"), "run --headless --script " + kScript +
                                                   " --seconds 0.1 --record " + fresh("d3.csv") +
                                                   " --db /dev/null"}) {
    const Finished device = run(command);
    EXPECT_EQ(device.exit_code, 2) << command;
    EXPECT_NE(device.err.find("/dev/null: not a regular file"), std::string::npos) << device.err;
  }
}

}  // namespace
