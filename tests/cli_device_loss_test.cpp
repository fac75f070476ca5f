// `imasim device-emulator` exiting in the middle of a cut, as a user's run meets it:
// from the step the loss is seen the hook cuts no more and both instruments hold
// still; the run says so on stderr, counts it in its JSON and records it in its input stream,
// whose replay gives the same state.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cli_process.hpp"

namespace {

using imasim::test::Finished;

std::string err_file(const std::string& stem) {
  return imasim::test::test_err_file(::testing::TempDir(), stem);
}

std::vector<std::string> fields_of(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> out;
  for (std::string f; in >> f;)
    out.push_back(f);
  return out;
}

TEST(RunDeviceLoss, AnEmulatorExitingMidCutLeavesTheHookHeldWithThePedalOff) {
  const std::string exe = IMASIM_EXE;
  const std::string script = std::string(IMASIM_SOURCE_DIR) + "/examples/open_fascia.script";
  const std::string stream = ::testing::TempDir() + "imasim_device_loss.stream";
  const std::string port = std::to_string(imasim::test::free_loopback_port());
  const std::string run_err = err_file("imasim_loss_run");
  // The emulator plays 1.5 s of the script, in the middle of its first cut (pedal down from
  // 0.5 s to 4.1 s), and exits; the run goes on to 3 s.
  const Finished f = imasim::test::run_shell(
      exe + " run --headless --devices openigtlink --igtl-port " + port +
          " --seconds 3 --threads 1 --record-input " + stream + " --json 2>" + run_err +
          " & pid=$!; " + exe + " device-emulator --port " + port + " --seconds 1.5 --script " +
          script + " --wait 20 >/dev/null 2>" + err_file("imasim_loss_emulator") + "; wait $pid",
      run_err);
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const auto j = nlohmann::json::parse(f.out);
  EXPECT_EQ(j["status"], "ok");
  EXPECT_EQ(j["steps"], 600);

  // The stream, step by step: the right instrument's pedal is field 33, a loss the last field.
  int cut_before = 0, lost_steps = 0, cut_after = 0;
  bool lost = false;
  for (const std::string& line : imasim::test::lines_of(imasim::test::read_file(stream))) {
    const std::vector<std::string> fields = fields_of(line);
    if (fields.empty() || fields[0][0] == '#') continue;
    ASSERT_GE(fields.size(), 38u) << line;
    const bool marked = fields.size() == 39 && fields[38] == "lost:both";
    if (marked && !lost) lost = true;
    if (lost) {
      EXPECT_TRUE(marked) << line;  // once lost, lost to the end: the emulator does not return
      ++lost_steps;
      cut_after += fields[33] == "cut" ? 1 : 0;
    } else {
      cut_before += fields[33] == "cut" ? 1 : 0;
    }
  }
  EXPECT_GT(cut_before, 50);  // it cut while the emulator played
  EXPECT_EQ(cut_after, 0);    // and not a step after it left
  EXPECT_GT(lost_steps, 100);

  EXPECT_EQ(j["events"]["device_lost"], 2);  // both instruments
  EXPECT_EQ(j["events"]["device_restored"], 0);
  const auto& lost_report = j["devices"]["lost"];
  for (const char* part : {"left", "right", "pedal"}) {
    EXPECT_EQ(lost_report[part]["losses"], 1) << part;
    EXPECT_EQ(lost_report[part]["held_at_end"], true) << part;
    EXPECT_GT(lost_report[part]["lost_s"].get<double>(), 0.4) << part;
  }
  EXPECT_NE(f.err.find("the hook's device was lost"), std::string::npos) << f.err;

  // The replay holds the instruments at the same steps: the same state.
  const Finished replay = imasim::test::run_imasim(
      "run --headless --replay " + stream + " --threads 2 --json", err_file("imasim_loss_replay"));
  ASSERT_EQ(replay.exit_code, 0) << replay.err;
  const auto r = nlohmann::json::parse(replay.out);
  EXPECT_EQ(r["state_hash"], j["state_hash"]);
  EXPECT_EQ(r["events"]["device_lost"], 2);
  EXPECT_EQ(r["fascia_edges_cut"], j["fascia_edges_cut"]);
}

}  // namespace
