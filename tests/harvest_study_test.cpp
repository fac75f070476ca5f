// The scripted operator's study, as `imasim experiment` runs it: patients harvested
// with the beating and with the static heart, two trials at a time. The operator must finish the
// task (its plan completed, at least 90 % of the pedicle's strands divided, the fascia opened)
// with the IMA uninjured in at least 9 of 10 trials per mode, and the two groups' SAI must differ
// as the operator's stated reason says (it keeps further from a beating heart).
// The full study (ten patients, about 25 minutes on 2 cores) has its label `harvest` and
// `make harvest-check`; CI runs the first four patients (label `harvest-ci`, about 9 minutes,
// `make harvest-ci`), the same bar scaled: 0.9 x 4 rounds up to all four.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_process.hpp"

namespace {

using imasim::test::read_file;

// Runs the study of `patients` patients per mode and checks the operator's bar: at least
// ceil(0.9 n) trials per mode finished with the IMA uninjured, and the beating heart's mean SAI
// above the static one's.
void expect_the_operator_meets_its_bar(int patients, const std::string& name) {
  const std::string out = ::testing::TempDir() + name;
  std::filesystem::remove_all(out);
  const imasim::test::Finished f = imasim::test::run_shell(
      std::string(IMASIM_EXE) + " experiment --trials " + std::to_string(patients) +
          " --modes dynamic,static --seed 1 --jobs 2 --no-db --json --out " + out,
      out + ".err");
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const int bar = static_cast<int>(std::ceil(0.9 * patients - 1e-9));
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
    EXPECT_EQ(trials, patients);
    EXPECT_GE(finished, bar) << mode;
    EXPECT_GE(uninjured, bar) << mode;
  }
  const nlohmann::json& hook = results["sai"]["hook"];
  EXPECT_GT(hook["groups"]["dynamic"]["mean"].get<double>(),
            hook["groups"]["static"]["mean"].get<double>());
}

TEST(HarvestStudy, TheOperatorFinishesNineOfTenPerModeWithTheImaUninjured) {
  expect_the_operator_meets_its_bar(10, "imasim_harvest_study");
}

TEST(HarvestStudyFirstPatients, TheOperatorFinishesAllFourPerModeWithTheImaUninjured) {
  expect_the_operator_meets_its_bar(4, "imasim_harvest_study_first_patients");
}

}  // namespace
