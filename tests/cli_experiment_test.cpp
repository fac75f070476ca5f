// `imasim experiment` as a user runs it: four short trials of the example script in two processes
// at a time, one of them stopped (SIGSTOP, a hung trial) and killed by --trial-timeout while the
// others are kept; the report, results.json and trials.csv hold every trial; Ctrl-C (SIGINT)
// still writes the report of what finished; bad requests are refused with a message.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli_process.hpp"

namespace {

using imasim::test::Finished;
using imasim::test::lines_of;
using imasim::test::read_file;

const std::string kDir = ::testing::TempDir();
const std::string kScript = IMASIM_SOURCE_DIR "/examples/open_fascia.script";
// Longer than a 0.5 s trial takes here (a few seconds) with room for a loaded machine; the
// stopped trial waits for it.
constexpr int kTrialTimeout = 15;

// Runs `imasim ARGS` in the background, then `while_running` (a shell snippet with $P, the
// experiment's pid), and waits for it; its exit status is printed last on stdout as "exit=N".
Finished experiment(const std::string& args, const std::string& while_running,
                    const std::string& name) {
  const std::string err = kDir + name + ".err";
  // Each study's trials append to records of its own, never to the user's.
  const std::string db = kDir + name + ".sqlite";
  std::remove(db.c_str());
  const std::string records = args.find("--no-db") == std::string::npos ? " --db " + db : "";
  const std::string script = std::string(IMASIM_EXE) + " experiment " + args + records + " >" +
                             kDir + name + ".out 2>" + err + " & P=$!; " + while_running +
                             "; wait $P; echo exit=$?";
  Finished f = imasim::test::run_shell("sh -c '" + script + "'", err);
  f.out = read_file(kDir + name + ".out") + f.out;
  return f;
}

int exit_status(const Finished& f) {
  const std::size_t at = f.out.rfind("exit=");
  return at == std::string::npos ? -1 : std::stoi(f.out.substr(at + 5));
}

std::size_t field_count(const std::string& line) {
  return std::size_t(std::count(line.begin(), line.end(), ',')) + 1;
}

// Waits (at most 20 s) for the experiment's first child and stops it.
const std::string kStopOneTrial =
    "for i in $(seq 200); do C=$(pgrep -P $P | head -n 1); [ -n \"$C\" ] && break; sleep 0.1; "
    "done; kill -STOP $C";

TEST(CliExperiment, AStoppedTrialIsKilledByItsTimeoutAndTheOthersAreKept) {
  const std::string out = kDir + "imasim_study";
  const Finished f = experiment("--trials 2 --modes dynamic,static --script " + kScript +
                                    " --seconds 0.5 --jobs 2 --out " + out + " --trial-timeout " +
                                    std::to_string(kTrialTimeout) + " --json --no-db",
                                kStopOneTrial, "imasim_study");
  ASSERT_EQ(exit_status(f), 0) << f.out << f.err;
  const nlohmann::json summary = nlohmann::json::parse(f.out.substr(0, f.out.rfind("exit=")));
  EXPECT_EQ(summary["trials"], 4);
  EXPECT_EQ(summary["trials_ok"], 3);
  EXPECT_EQ(summary["trials_failed"], 1);
  EXPECT_EQ(summary["report"], out + "/report.html");

  const nlohmann::json results = nlohmann::json::parse(read_file(out + "/results.json"));
  EXPECT_EQ(results["format"], "imasim study v1");
  EXPECT_EQ(results["study"]["operator"], "script");
  EXPECT_EQ(results["study"]["modes"], nlohmann::json({"dynamic", "static"}));
  EXPECT_EQ(results["headline"]["instrument"], "hook");
  const nlohmann::json& trials = results["trials"];
  ASSERT_EQ(trials.size(), 4u);
  int failed = 0;
  for (const nlohmann::json& t : trials) {
    const std::string stem = out + "/trials/" + t["mode"].get<std::string>() + "-0" +
                             std::to_string(t["trial"].get<int>());
    EXPECT_EQ(t["files"]["log"], stem + ".log");
    if (t["status"] == "failed") {
      ++failed;
      EXPECT_EQ(t["reason"], "timed out after " + std::to_string(kTrialTimeout) +
                                 " s of wall-clock time (killed)");
      EXPECT_GE(t["wall_s"].get<double>(), kTrialTimeout);
      continue;
    }
    // The trial's scores are its recording's side file's, and its stdout is the run's report.
    const nlohmann::json side = nlohmann::json::parse(read_file(stem + ".json"));
    EXPECT_EQ(t["sai"]["hook"]["sai"], side["run"]["scores"]["sai"]["hook"]["sai"]);
    EXPECT_EQ(t["sai"]["forceps"]["samples"], 31);  // 0.5 s at 60 Hz
    const nlohmann::json report = nlohmann::json::parse(read_file(stem + ".report.json"));
    EXPECT_EQ(report["status"], "ok");
    EXPECT_EQ(report["patient_seed"], t["patient_seed"]);
    EXPECT_EQ(report["heart"], t["mode"] == "static" ? "static" : "beating");
    EXPECT_EQ(t["metrics"].size(), side["run"]["scores"]["metrics"].size());
  }
  EXPECT_EQ(failed, 1);
  // Trial k is the same patient in both modes; trials 1 and 2 are different patients.
  EXPECT_EQ(trials[0]["patient_seed"], trials[2]["patient_seed"]);
  EXPECT_EQ(trials[1]["patient_seed"], trials[3]["patient_seed"]);
  EXPECT_NE(trials[0]["patient_seed"], trials[1]["patient_seed"]);

  // One row a trial, the same fields in every row.
  const std::vector<std::string> rows = lines_of(read_file(out + "/trials.csv"));
  ASSERT_EQ(rows.size(), 5u);
  EXPECT_EQ(rows[0].rfind("mode,trial,patient_seed,operator_seed,status,reason,wall_s,"
                          "sai_forceps,sai_hook,time_to_complete_s,",
                          0),
            0u)
      << rows[0];
  for (const std::string& row : rows)
    EXPECT_EQ(field_count(row), field_count(rows[0])) << row;
  EXPECT_EQ(std::count_if(rows.begin(), rows.end(),
                          [](const std::string& r) {
                            return r.find(",failed,timed out") != std::string::npos;
                          }),
            1);

  const std::string page = read_file(out + "/report.html");
  EXPECT_NE(page.find("Table 1. Spatial Asymmetry Index per trial"), std::string::npos);
  EXPECT_NE(page.find("<tr><td>1</td>"), std::string::npos);
  EXPECT_NE(page.find("<tr><td>2</td>"), std::string::npos);
  EXPECT_NE(page.find("title=\"timed out after"), std::string::npos);  // its cell in Table 1
  EXPECT_NE(page.find("the input script " + kScript), std::string::npos);

  // No trainee records were asked for: the report has no history.
  EXPECT_EQ(page.find("Trainee history"), std::string::npos);
}

TEST(CliExperiment, TheTrialsGoToTheTraineeRecordsAndTheReportPlotsTheirHistory) {
  const std::string out = kDir + "imasim_study_records";
  std::filesystem::remove_all(out);
  const Finished f = experiment("--trials 2 --modes dynamic,static --script " + kScript +
                                    " --seconds 0.3 --jobs 2 --trainee study_operator --out " + out,
                                "true", "imasim_study_records");
  ASSERT_EQ(exit_status(f), 0) << f.out << f.err;
  const Finished history = imasim::test::run_shell(
      std::string(IMASIM_EXE) + " history --db " + kDir + "imasim_study_records.sqlite --json",
      kDir + "imasim_study_records_history.err");
  const nlohmann::json h = nlohmann::json::parse(history.out);
  ASSERT_EQ(h["trainees"].size(), 1u) << history.out;
  EXPECT_EQ(h["trainees"][0]["trainee"], "study_operator");
  EXPECT_EQ(h["trainees"][0]["sessions"].size(), 4u);
  const std::string page = read_file(out + "/report.html");
  EXPECT_NE(page.find("Trainee history"), std::string::npos);
  EXPECT_NE(page.find("4 recorded sessions"), std::string::npos);
  EXPECT_NE(page.find("Table 5. The sessions of &#39;study_operator&#39;"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(out + "/history-sai.png"));
  EXPECT_TRUE(std::filesystem::exists(out + "/history-passed.png"));
}

TEST(CliExperiment, CtrlCStillWritesTheReportOfWhatFinished) {
  const std::string out = kDir + "imasim_study_interrupted";
  // One trial at a time: once the second has started (its log exists), the first is done;
  // interrupt the study then.
  const std::string second = out + "/trials/static-02.log";
  std::filesystem::remove_all(out);
  const Finished f = experiment(
      "--trials 2 --modes static --script " + kScript + " --seconds 0.5 --jobs 1 --out " + out,
      "for i in $(seq 600); do [ -e " + second + " ] && break; sleep 0.1; done; kill -INT $P",
      "imasim_study_interrupted");
  EXPECT_EQ(exit_status(f), 130) << f.out << f.err;
  EXPECT_NE(f.out.find("Report: " + out + "/report.html"), std::string::npos) << f.out;
  const nlohmann::json results = nlohmann::json::parse(read_file(out + "/results.json"));
  EXPECT_EQ(results["study"]["status"], "interrupted");
  ASSERT_EQ(results["trials"].size(), 2u);
  EXPECT_EQ(results["trials"][0]["status"], "ok");
  EXPECT_EQ(results["trials"][1]["status"], "failed");
  EXPECT_EQ(results["trials"][1]["reason"], "interrupted (the study was stopped)");
  // The interrupted trial left the trainee records alone; the rerun runs it and records it: the
  // records hold each trial once (they held the interrupted one too, and then the rerun's).
  const std::string db = kDir + "imasim_study_interrupted.sqlite";
  const std::string err = kDir + "imasim_study_interrupted_rerun.err";
  auto sessions = [&] {
    const Finished history =
        imasim::test::run_shell(std::string(IMASIM_EXE) + " history --db " + db + " --json", err);
    const nlohmann::json h = nlohmann::json::parse(history.out);
    return h["trainees"].empty() ? std::size_t(0) : h["trainees"][0]["sessions"].size();
  };
  EXPECT_EQ(sessions(), 1u);
  const Finished rerun = imasim::test::run_shell(
      std::string(IMASIM_EXE) + " experiment --trials 2 --modes static --script " + kScript +
          " --seconds 0.5 --jobs 1 --out " + out + " --db " + db + " --json 2>" + err,
      err);
  ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
  EXPECT_EQ(nlohmann::json::parse(rerun.out)["trials_kept"], 1);
  EXPECT_EQ(sessions(), 2u);
}

// A study killed with SIGKILL left its running trial an orphan that went on (and wrote its
// records); its rerun redid every trial. Now the trial dies with the study, and the rerun keeps
// the trial that finished (its manifest and files unchanged) and runs only the other: the records
// hold each trial once.
TEST(CliExperiment, AKilledStudyLeavesNoOrphanAndItsRerunKeepsWhatFinished) {
  const std::string out = kDir + "imasim_study_killed";
  const std::string second = out + "/trials/static-02.log";
  std::filesystem::remove_all(out);
  const std::string args =
      "--trials 2 --modes static --script " + kScript + " --seconds 2 --jobs 1 --out " + out;
  const Finished killed = experiment(
      args,
      "for i in $(seq 600); do [ -e " + second +
          " ] && break; sleep 0.1; done; C=$(pgrep -P $P | head -n 1); kill -9 $P; sleep 0.5; "
          "S=$(awk \"/^State/{print \\$2}\" /proc/$C/status 2>/dev/null); "
          "if [ -z \"$S\" ] || [ \"$S\" = Z ]; then echo orphan=gone; "
          "else echo orphan=alive; kill -9 $C; fi",
      "imasim_study_killed");
  EXPECT_EQ(exit_status(killed), 137) << killed.out << killed.err;
  EXPECT_NE(killed.out.find("orphan=gone"), std::string::npos) << killed.out;
  ASSERT_TRUE(std::filesystem::exists(out + "/trials/static-01.done.json"));
  EXPECT_FALSE(std::filesystem::exists(out + "/trials/static-02.done.json"));

  // The rerun, on the same records (the helper starts each study with records of its own).
  const std::string db = kDir + "imasim_study_killed.sqlite";
  const std::string err = kDir + "imasim_study_killed_rerun.err";
  const Finished rerun = imasim::test::run_shell(
      std::string(IMASIM_EXE) + " experiment " + args + " --db " + db + " --json 2>" + err, err);
  ASSERT_EQ(rerun.exit_code, 0) << rerun.err;
  EXPECT_NE(rerun.err.find("1 of 2 trials kept from an earlier run of this study in " + out),
            std::string::npos)
      << rerun.err;
  const nlohmann::json summary = nlohmann::json::parse(rerun.out);
  EXPECT_EQ(summary["trials_kept"], 1);
  EXPECT_EQ(summary["trials_ok"], 2);
  const Finished history =
      imasim::test::run_shell(std::string(IMASIM_EXE) + " history --db " + db + " --json", err);
  const nlohmann::json h = nlohmann::json::parse(history.out);
  ASSERT_EQ(h["trainees"].size(), 1u) << history.out;
  EXPECT_EQ(h["trainees"][0]["sessions"].size(), 2u);  // one per trial
}

// `render --frames 100000` at 8192x8192 began about two days and terabytes of work without a
// word, `experiment --trials 1000 --seconds 3600` two thousand hour-long trials. Long jobs say
// their cost and wait for --yes above an hour or 10 GB; small ones say it and go on.
TEST(CliExperiment, LongJobsSayTheirCostAndWaitForYes) {
  const std::string render_out = kDir + "imasim_huge_render", study_out = kDir + "imasim_huge";
  std::filesystem::remove_all(render_out);
  std::filesystem::remove_all(study_out);
  const std::string err = kDir + "imasim_long_jobs.err";
  const Finished render = imasim::test::run_shell(
      std::string(IMASIM_EXE) + " render --frames 100000 --width 8192 --height 8192 --out " +
          render_out + " 2>" + err,
      err);
  EXPECT_EQ(render.exit_code, 2);
  EXPECT_NE(render.err.find("imasim render: 100000 frames of 8192x8192: about "), std::string::npos)
      << render.err;
  EXPECT_NE(render.err.find("TB of work"), std::string::npos) << render.err;
  EXPECT_NE(render.err.find("add --yes to start it"), std::string::npos) << render.err;
  EXPECT_FALSE(std::filesystem::exists(render_out));  // nothing begun
  const Finished study = imasim::test::run_shell(
      std::string(IMASIM_EXE) + " experiment --trials 1000 --modes dynamic,static --seconds 3600 " +
          "--jobs 2 --no-db --out " + study_out + " 2>" + err,
      err);
  EXPECT_EQ(study.exit_code, 2);
  EXPECT_NE(study.err.find("imasim experiment: 2000 trials of 3600 s, 2 at once: about 850 h"),
            std::string::npos)
      << study.err;
  EXPECT_NE(study.err.find("add --yes to start it"), std::string::npos) << study.err;
  EXPECT_FALSE(std::filesystem::exists(study_out));
}

TEST(CliExperiment, BadRequestsAreRefusedWithAMessage) {
  const Finished twice = experiment("--trials 2 --modes dynamic,dynamic --script " + kScript +
                                        " --out " + kDir + "imasim_study_bad",
                                    "true", "imasim_study_bad");
  EXPECT_EQ(exit_status(twice), 2);
  EXPECT_NE(twice.err.find("--modes names 'dynamic' twice"), std::string::npos) << twice.err;
  const Finished missing = experiment(
      "--trials 2 --modes static --script /nonexistent.script"
      " --out " +
          kDir + "imasim_study_bad",
      "true", "imasim_study_bad");
  EXPECT_EQ(exit_status(missing), 2);
  EXPECT_NE(missing.err.find("/nonexistent.script"), std::string::npos) << missing.err;
  const Finished mode = experiment("--trials 2 --modes beating --out " + kDir + "imasim_study_bad",
                                   "true", "imasim_study_bad");
  EXPECT_NE(exit_status(mode), 0);
  EXPECT_NE(mode.err.find("beating"), std::string::npos) << mode.err;
}

}  // namespace
