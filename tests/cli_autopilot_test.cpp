// `imasim run --autopilot` as a user meets it: the scripted operator drives both instruments,
// the run reports its plan and how far it got, the same state on one thread and on two, and
// inputs of another kind are refused beside it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "cli_process.hpp"

namespace {

const std::string kDir = ::testing::TempDir();

imasim::test::Finished run(const std::string& args, const std::string& name) {
  const std::string err = kDir + name + ".err";
  return imasim::test::run_shell(std::string(IMASIM_EXE) + " run --headless " + args + " 2>" + err,
                                 err);
}

TEST(RunAutopilot, TheOperatorDrivesTheInstrumentsTheSameOnOneAndTwoThreads) {
  const imasim::test::Finished one =
      run("--autopilot --seconds 1.5 --threads 1 --json", "imasim_autopilot_1");
  const imasim::test::Finished two =
      run("--autopilot --seconds 1.5 --threads 2 --json", "imasim_autopilot_2");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  ASSERT_EQ(two.exit_code, 0) << two.err;
  const nlohmann::json a = nlohmann::json::parse(one.out), b = nlohmann::json::parse(two.out);
  EXPECT_EQ(a["status"], "ok");
  EXPECT_EQ(a["input"], "autopilot");
  EXPECT_EQ(a["state_hash"], b["state_hash"]);
  const nlohmann::json& op = a["operator"];
  EXPECT_EQ(op["phase_reached"], "open");
  EXPECT_FALSE(op["plan_completed"].get<bool>());
  EXPECT_FALSE(op["task_finished"].get<bool>());
  EXPECT_GT(op["plan_s"].get<double>(), 60);
  EXPECT_EQ(op["phases"].size(), 4u);
  EXPECT_GT(op["heart_excursion_m"].get<double>(), 0.001);  // the beating heart
  EXPECT_GT(op["keep_out_m"].get<double>(), 0.002);
  EXPECT_GT(op["pedicle_strands"].get<int>(), 50);
  // The instruments moved: the hook reached the fascia within 1.5 s.
  EXPECT_GT(a["events"]["contact_begin"].get<int>(), 0);
}

TEST(RunAutopilot, OtherInputsAndBadParametersAreRefused) {
  const imasim::test::Finished script =
      run("--autopilot --script " IMASIM_SOURCE_DIR "/examples/open_fascia.script",
          "imasim_autopilot_script");
  EXPECT_EQ(script.exit_code, 2);
  EXPECT_NE(script.err.find("--autopilot drives the instruments itself"), std::string::npos)
      << script.err;
  const imasim::test::Finished speed = run("--autopilot --operator-speed 0", "imasim_autopilot_0");
  EXPECT_EQ(speed.exit_code, 105);  // CLI11's code for a value its check refuses, as elsewhere
  EXPECT_NE(speed.err.find("--operator-speed"), std::string::npos) << speed.err;
}

}  // namespace
