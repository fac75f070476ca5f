// What `imasim run` refuses from its OpenIGTLink peers is said, not swallowed: a tracker
// sending under a name the scene does not map has every pose
// refused; stderr says so once, the JSON counts it by reason and by device name.
#include <gtest/gtest.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_process.hpp"

namespace {

std::string err_file(const std::string& stem) {
  return imasim::test::test_err_file(::testing::TempDir(), stem);
}

TEST(RunRefusals, AnUnmappedTrackerIsCountedByNameAndSaidOnceOnStderr) {
  const std::string exe = IMASIM_EXE;
  const std::string script = std::string(IMASIM_SOURCE_DIR) + "/examples/open_fascia.script";
  // The emulator's console calls its left hand "Tracker"; the run maps the default names.
  const std::string scene = ::testing::TempDir() + "imasim_tracker.toml";
  std::ofstream(scene) << "[devices]\nleft_hand = \"Tracker\"\n";
  const std::string port = std::to_string(imasim::test::free_loopback_port());
  const std::string run_err = err_file("imasim_refusals_run");
  const imasim::test::Finished f = imasim::test::run_shell(
      exe + " run --headless --devices openigtlink --igtl-port " + port +
          " --seconds 1.5 --threads 1 --json 2>" + run_err + " & pid=$!; " + exe +
          " device-emulator --port " + port + " --seconds 1 --script " + script + " --scene " +
          scene + " --wait 20 >/dev/null 2>" + err_file("imasim_refusals_emulator") + "; wait $pid",
      run_err);
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const auto j = nlohmann::json::parse(f.out);
  const auto& d = j["devices"];
  const auto& refused = d["refused"];
  EXPECT_GT(refused["by_reason"]["unknown_device"].get<int>(), 500);  // 1 kHz for about 1 s
  EXPECT_EQ(refused["by_device"]["Tracker"], refused["by_reason"]["unknown_device"]);
  EXPECT_EQ(refused["total"], refused["by_reason"]["unknown_device"]);
  EXPECT_EQ(d["peers_seen"], 1);
  // Said once, naming the reason; the right hand, correctly named, was followed.
  const std::string said = "OpenIGTLink: a message was refused (unknown_device";
  const std::size_t first = f.err.find(said);
  EXPECT_NE(first, std::string::npos) << f.err;
  EXPECT_EQ(f.err.find(said, first + 1), std::string::npos) << f.err;
}

// `devices` without --listen refuses the options that only listening reads, the default value
// too, naming what they need.
TEST(DevicesListen, SecondsAndPortWithoutListenAreRefusedNamingIt) {
  const std::string exe = IMASIM_EXE;
  for (const std::string args : {"--seconds 10", "--seconds 3", "--igtl-port 18944"}) {
    const std::string err = err_file("imasim_devices_needs");
    const imasim::test::Finished f =
        imasim::test::run_shell(exe + " devices " + args + " 2>" + err, err);
    EXPECT_NE(f.exit_code, 0) << args;
    EXPECT_NE(f.err.find("requires --listen"), std::string::npos) << args << ": " << f.err;
  }
}

// `devices --listen` shows what arrives and what each name becomes: a tracker calling its left
// hand "Tracker" is seen by that name, refused, and told how to map it.
TEST(DevicesListen, ShowsEachArrivingNameAndTypeAndWhatItBecomes) {
  const std::string exe = IMASIM_EXE;
  const std::string script = std::string(IMASIM_SOURCE_DIR) + "/examples/open_fascia.script";
  const std::string scene = ::testing::TempDir() + "imasim_listen_tracker.toml";
  std::ofstream(scene) << "[devices]\nleft_hand = \"Tracker\"\n";
  const std::string port = std::to_string(imasim::test::free_loopback_port());
  const std::string listen_err = err_file("imasim_listen");
  const imasim::test::Finished f = imasim::test::run_shell(
      exe + " devices --listen --seconds 1.5 --igtl-port " + port + " --json 2>" + listen_err +
          " & pid=$!; " + exe + " device-emulator --port " + port + " --seconds 1 --script " +
          script + " --scene " + scene + " --wait 20 >/dev/null 2>" +
          err_file("imasim_listen_emulator") + "; wait $pid",
      listen_err);
  ASSERT_EQ(f.exit_code, 0) << f.err;
  const auto j = nlohmann::json::parse(f.out);
  EXPECT_EQ(j["peers_seen"], 1);
  std::map<std::string, nlohmann::json> by_name;
  for (const auto& a : j["arrivals"])
    by_name[a["type"].get<std::string>() + " " + a["name"].get<std::string>()] = a;
  ASSERT_TRUE(by_name.count("TRANSFORM Tracker")) << f.out;
  const auto& tracker = by_name["TRANSFORM Tracker"];
  EXPECT_GT(tracker["messages"].get<int>(), 500);
  EXPECT_EQ(tracker["accepted"], 0);
  EXPECT_NE(tracker["becomes"].get<std::string>().find("devices.left_hand"), std::string::npos);
  ASSERT_TRUE(by_name.count("TRANSFORM RightTool")) << f.out;
  EXPECT_EQ(by_name["TRANSFORM RightTool"]["accepted"], by_name["TRANSFORM RightTool"]["messages"]);
  EXPECT_EQ(by_name["TRANSFORM RightTool"]["becomes"], "right tool's pose (devices.right_tool)");
  EXPECT_TRUE(by_name.count("SENSOR Pedal")) << f.out;
  EXPECT_EQ(j["refused"]["unknown_device"], tracker["messages"]);
}

}  // namespace
