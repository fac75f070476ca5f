// The scripted operator's study (issue 14), as `imasim experiment` runs it: ten patients, each
// harvested with the beating and with the static heart, two trials at a time. The operator must
// finish the task (its plan completed, at least 90 % of the pedicle's strands divided, the fascia
// opened) with the IMA uninjured in at least 9 of 10 trials per mode, and the two groups' SAI
// must differ as the operator's stated reason says (it keeps further from a beating heart).
// About 25 minutes of CPU: its own binary and label (`make harvest-check`).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_process.hpp"

namespace {

using imasim::test::read_file;

TEST(HarvestStudy, TheOperatorFinishesNineOfTenPerModeWithTheImaUninjured) {
  const std::string out = ::testing::TempDir() + "imasim_harvest_study";
  std::filesystem::remove_all(out);
  const imasim::test::Finished f = imasim::test::run_shell(
      std::string(IMASIM_EXE) + " experiment --trials 10 --modes dynamic,static --seed 1 " +
          "--jobs 2 --no-db --json --out " + out,
      out + ".err");
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const nlohmann::json results = nlohmann::json::parse(read_file(out + "/results.json"));
  for (const std::string mode : {"dynamic", "static"}) {
    int finished = 0, uninjured = 0, trials = 0;
    for (const nlohmann::json& t : results["trials"]) {
      if (t["mode"] != mode) continue;
      ++trials;
      ASSERT_EQ(t["status"], "ok") << t.dump();
      const nlohmann::json report =
          nlohmann::json::parse(read_file(t["files"]["report"].get<std::string>()));
      const nlohmann::json& op = report["operator"];
      EXPECT_TRUE(op["plan_completed"].get<bool>()) << op.dump();
      finished += op["task_finished"].get<bool>() ? 1 : 0;
      uninjured += op["ima_injuries"].get<int>() == 0 ? 1 : 0;
    }
    EXPECT_EQ(trials, 10);
    EXPECT_GE(finished, 9) << mode;
    EXPECT_GE(uninjured, 9) << mode;
  }
  const nlohmann::json& hook = results["sai"]["hook"];
  EXPECT_GT(hook["groups"]["dynamic"]["mean"].get<double>(),
            hook["groups"]["static"]["mean"].get<double>());
}

}  // namespace
