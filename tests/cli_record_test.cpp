// `imasim run --record FILE.csv` as a user meets it: a 60 Hz CSV whose every line has a field per
// column, a side file naming each column, the events beside it, and a run killed with SIGKILL
// leaving whole rows up to its last flush.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_process.hpp"

namespace {

using imasim::test::Finished;
using imasim::test::lines_of;
using imasim::test::read_file;

const std::string kDir = ::testing::TempDir();
std::string err_file() {
  return imasim::test::test_err_file(kDir, "imasim_record");
}
const std::string kScript = IMASIM_SOURCE_DIR "/examples/open_fascia.script";

// Recorded runs append to the trainee records of the user's data directory: here a temporary
// one, never the real user's.
const std::string kDataHome = kDir + "imasim_record_data_home";

Finished run(const std::string& args, const std::string& prefix = "") {
  return imasim::test::run_imasim(args, err_file(), prefix + " env XDG_DATA_HOME=" + kDataHome);
}

std::size_t field_count(const std::string& line) {
  return std::size_t(std::count(line.begin(), line.end(), ',')) + 1;
}

TEST(RunRecord, SixtyHertzRowsASideFileAndTheEvents) {
  const std::string csv = kDir + "imasim_record_run.csv";
  const Finished f = run("run --headless --script " + kScript + " --seconds 1 --threads 1 " +
                         "--record " + csv + " --json");
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const nlohmann::json report = nlohmann::json::parse(f.out);
  EXPECT_EQ(report["recorded_rows"], 61);  // 0 to 1 s at 60 Hz
  const std::string text = read_file(csv);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');
  const std::vector<std::string> lines = lines_of(text);
  ASSERT_EQ(lines.size(), 62u);
  const std::size_t columns = field_count(lines[0]);
  for (const std::string& line : lines)
    EXPECT_EQ(field_count(line), columns) << line;
  EXPECT_EQ(lines[0].rfind("t_s,forceps_x,forceps_y,forceps_z,", 0), 0u) << lines[0];
  EXPECT_EQ(lines[1].rfind("0,", 0), 0u) << lines[1];  // the state before the first step
  // The cautery cuts from 0.5 s: the pedal column says so.
  EXPECT_NE(lines.back().find(",cut,40"), std::string::npos) << lines.back();

  const nlohmann::json side = nlohmann::json::parse(read_file(kDir + "imasim_record_run.json"));
  EXPECT_EQ(side["rate_hz"], 60);
  EXPECT_EQ(side["run"]["heart"], "dynamic");
  EXPECT_EQ(side["run"]["status"], "ok");
  EXPECT_EQ(side["run"]["rows"], 61);
  ASSERT_EQ(side["columns"].size(), columns);
  EXPECT_EQ(side["columns"][0]["name"], "t_s");
  const std::string events = read_file(kDir + "imasim_record_run.events.csv");
  EXPECT_NE(events.find(",cautery_on,right,"), std::string::npos) << events;

  // The run scores its recording (eq. 20), and `imasim sai` on the files it wrote agrees.
  ASSERT_TRUE(report.contains("scores")) << f.out;
  const nlohmann::json& scores = report["scores"];
  EXPECT_EQ(scores["sai"]["radius_m"], 0.002);
  EXPECT_EQ(side["run"]["scores"], scores);
  // Every trainee metric with its threshold and verdict.
  EXPECT_EQ(scores["metrics"].size(), scores["metrics_total"]);
  EXPECT_GE(scores["metrics"].size(), 15u);
  for (const auto& m : scores["metrics"]) {
    EXPECT_TRUE(m.contains("threshold") && m.contains("pass") && m.contains("unit")) << m;
    if (m["name"] == "cautery_on_s") {
      EXPECT_NEAR(m["value"].get<double>(), 0.5, 0.02) << m;  // the pedal from 0.5 s
    }
    if (m["name"] == "time_to_complete_s") {
      EXPECT_NEAR(m["value"].get<double>(), 1.0, 1e-9) << m;
    }
  }
  for (const std::string tool : {"forceps", "hook"}) {
    const nlohmann::json mine = scores["sai"][tool];
    EXPECT_EQ(mine["samples"], 61) << tool;
    const Finished again = run("sai --trajectory " + csv + " --tool " + tool + " --centerline " +
                               kDir + "imasim_record_run.centerline.csv --heart " + kDir +
                               "imasim_record_run.heart.obj --json");
    ASSERT_EQ(again.exit_code, 0) << again.err;
    const nlohmann::json theirs = nlohmann::json::parse(again.out);
    EXPECT_EQ(theirs["samples"], 61) << tool;
    // The CSV keeps 9 significant digits of each tip: a few nanometres.
    EXPECT_NEAR(theirs["sai"].get<double>(), mine["sai"].get<double>(), 1e-5) << tool;
    EXPECT_NEAR(theirs["mean_distance_m"].get<double>(), mine["mean_distance_m"].get<double>(),
                1e-8)
        << tool;
    EXPECT_EQ(theirs["heart_side_fraction"], mine["heart_side_fraction"]) << tool;
  }
}

TEST(RunRecord, AKilledRunKeepsWholeRowsUpToItsLastFlush) {
  const std::string csv = kDir + "imasim_record_killed.csv";
  const Finished f = run("run --headless --script " + kScript + " --seconds 60 --threads 1 " +
                             "--record " + csv + " --json",
                         "timeout -s KILL 5");
  EXPECT_EQ(f.exit_code, 137);
  const std::string text = read_file(csv);
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n');  // never half a row
  const std::vector<std::string> lines = lines_of(text);
  ASSERT_GE(lines.size(), 2u);  // rows flushed before the kill (the first step's at least)
  for (const std::string& line : lines)
    EXPECT_EQ(field_count(line), field_count(lines[0])) << line;
  // The side file was written at the start: the recording can be read without the run's end.
  const nlohmann::json side = nlohmann::json::parse(read_file(kDir + "imasim_record_killed.json"));
  EXPECT_FALSE(side["run"].contains("status"));
  EXPECT_EQ(side["columns"].size(), field_count(lines[0]));
}

TEST(RunRecord, AThresholdsFileSetsThePassMarks) {
  const std::string csv = kDir + "imasim_record_thresholds.csv";
  const std::string thresholds = kDir + "imasim_thresholds.json";
  { std::ofstream(thresholds) << "{\"time_to_complete_s\": 0.5}\n"; }
  const Finished f = run("run --headless --script " + kScript + " --seconds 1 --threads 1 " +
                         "--record " + csv + " --thresholds " + thresholds + " --json");
  ASSERT_EQ(f.exit_code, 0) << f.err;
  bool seen = false;
  const nlohmann::json report = nlohmann::json::parse(f.out);
  for (const auto& m : report["scores"]["metrics"]) {
    if (m["name"] != "time_to_complete_s") continue;
    seen = true;
    EXPECT_EQ(m["threshold"], 0.5);
    EXPECT_EQ(m["pass"], false);  // 1 s > 0.5 s
  }
  EXPECT_TRUE(seen);
  { std::ofstream(thresholds) << "{\n  \"heart_contact\": 1\n}\n"; }
  const Finished bad = run("run --headless --script " + kScript + " --seconds 0.1 --record " + csv +
                           " --thresholds " + thresholds);
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find(thresholds + ":2: 'heart_contact' is no metric; did you mean "
                                      "'heart_contacts'?"),
            std::string::npos)
      << bad.err;
  const Finished alone =
      run("run --headless --script " + kScript + " --seconds 0.1 --thresholds " + thresholds);
  EXPECT_EQ(alone.exit_code, 2);
  EXPECT_NE(alone.err.find("--thresholds goes with --record"), std::string::npos) << alone.err;
}

TEST(RunRecord, NeedsInstrumentsAndRefusesToOverwriteAnInput) {
  const Finished bare = run("run --headless --seconds 0.1 --record " + kDir + "imasim_r.csv");
  EXPECT_EQ(bare.exit_code, 2);
  EXPECT_NE(bare.err.find("--record needs instruments"), std::string::npos) << bare.err;
  // The script itself named as the recording (a copy, so nothing lands beside the sources).
  const std::string script = kDir + "imasim_record_input.csv";
  { std::ofstream(script) << read_file(kScript); }
  const Finished over =
      run("run --headless --script " + script + " --seconds 0.1 --record " + script);
  EXPECT_EQ(over.exit_code, 2);
  EXPECT_NE(over.err.find("imasim_record_input.csv"), std::string::npos) << over.err;
  EXPECT_EQ(read_file(script), read_file(kScript));  // untouched
}

}  // namespace
