// The window's physics thread (ui/sim_thread.hpp) without a window: it steps a scripted session,
// publishes frames and numbers, ends at its end time with a score card, pauses, restarts with
// the other heart mode and records; the keyboard reaches the session through the live console.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "devices/igtl_device.hpp"
#include "loopback_client.hpp"
#include "runner/input_source.hpp"
#include "scene/scene_file.hpp"
#include "ui/keyboard_mouse_device.hpp"
#include "ui/sim_thread.hpp"

namespace imasim::ui {
namespace {

using namespace std::chrono_literals;

surgery::InputScript example_script() {
  return surgery::load_input_script(std::string(IMASIM_SOURCE_DIR) +
                                    "/examples/open_fascia.script");
}

template <class Condition>
bool wait_for(Condition done, std::chrono::seconds limit = 60s) {
  const auto until = std::chrono::steady_clock::now() + limit;
  while (!done()) {
    if (std::chrono::steady_clock::now() > until) return false;
    std::this_thread::sleep_for(2ms);
  }
  return true;
}

TEST(SimThread, StepsPublishesAndEndsWithAScoreCard) {
  SimConfig config;
  config.realtime = false;
  config.end_s = 0.3;
  SimThread sim(config, std::make_unique<runner::ScriptInput>(example_script()));
  EXPECT_FALSE(sim.finished());
  sim.start();
  ASSERT_TRUE(wait_for([&] { return sim.finished(); }));
  LiveNumbers n;
  ASSERT_TRUE(sim.latest_numbers(n));
  EXPECT_EQ(n.state, SimState::finished);
  EXPECT_NEAR(n.time_s, 0.3, 1e-9);
  EXPECT_EQ(n.steps, 60u);
  EXPECT_TRUE(n.beating);
  EXPECT_EQ(n.power_w, 40);
  bool fresh = false;
  const render::RenderFrame* frame = sim.latest_frame(&fresh);
  ASSERT_NE(frame, nullptr);
  EXPECT_TRUE(fresh);
  EXPECT_NEAR(frame->time_s, 0.3, 1e-9) << "the last frame is the end's";
  EXPECT_FALSE(frame->surfaces.empty());
  const std::optional<ScoreCard> card = sim.score_card();
  ASSERT_TRUE(card.has_value());
  EXPECT_NEAR(card->duration_s, 0.3, 1e-9);
  EXPECT_GT(card->strands_total, 0u);
  EXPECT_FALSE(card->metrics.empty());
  EXPECT_EQ(sim.score_card_generation(), 1u);
  sim.stop();
  sim.stop();  // twice is fine
}

TEST(SimThread, PausesRestartsWithTheOtherHeartAndRecords) {
  const std::string dir = testing::TempDir() + "imasim_sim_thread/";
  std::filesystem::create_directories(dir);
  SimConfig config;
  config.realtime = false;
  config.record_path = dir + "take.csv";
  SimThread sim(config, std::make_unique<runner::ScriptInput>(example_script()));
  sim.set_recording(true);
  sim.start();
  LiveNumbers n;
  ASSERT_TRUE(wait_for([&] { return sim.latest_numbers(n) && n.time_s > 0.1; }));
  EXPECT_TRUE(n.recording);
  sim.set_paused(true);
  ASSERT_TRUE(wait_for([&] { return sim.latest_numbers(n) && n.state == SimState::paused; }));
  const double paused_at = n.time_s;
  std::this_thread::sleep_for(100ms);
  sim.latest_numbers(n);
  EXPECT_EQ(n.time_s, paused_at);
  const std::uint64_t first = n.session;
  sim.set_beating(false);
  sim.restart();
  sim.set_paused(false);
  ASSERT_TRUE(wait_for(
      [&] { return sim.latest_numbers(n) && n.session != first && n.state == SimState::running; }));
  EXPECT_FALSE(n.beating);
  EXPECT_FALSE(n.recording) << "a restart ends the recording";
  EXPECT_NEAR(n.time_s, double(n.steps) * 0.005, 1e-9) << "the new session's own time";
  sim.end_session();
  ASSERT_TRUE(wait_for([&] { return sim.finished(); }));
  EXPECT_FALSE(sim.score_card()->beating);
  sim.stop();
  std::ifstream csv(config.record_path);
  std::string header, row;
  ASSERT_TRUE(std::getline(csv, header));
  EXPECT_EQ(header.rfind("t_s,", 0), 0u) << header;
  EXPECT_TRUE(std::getline(csv, row));
  EXPECT_TRUE(std::filesystem::exists(dir + "take.json"));
}

TEST(SimThread, ABadSceneIsRefusedBeforeAnyThreadStarts) {
  SimConfig config;
  config.scene.ports.clear();  // no camera, no instrument ports
  EXPECT_THROW(SimThread(config, std::make_unique<runner::ScriptInput>(example_script())),
               std::exception);
}

TEST(ConsoleInputSource, TheKeyboardDrivesTheSessionThroughTheLiveConsole) {
  session::SurgicalSession s =
      session::make_surgical_session(scene::default_thorax_scene_params(), {});
  auto owned = std::make_unique<KeyboardMouseDevice>();
  KeyboardMouseDevice* keyboard = owned.get();
  std::vector<std::unique_ptr<devices::InputDevice>> list;
  list.push_back(std::move(owned));
  console::LiveConsoleParams params;
  params.loop.realtime_priority = 0;
  runner::ConsoleInputSource source(std::move(list), params, [keyboard] { keyboard->reset(); });
  keyboard->set_held(Control::right_x_plus, true);
  keyboard->set_held(Control::pedal_coag, true);
  session::SessionInput in;
  ASSERT_TRUE(wait_for(
      [&] {
        in = source.next(s);
        return in.right.pose.translation.x() > 0.003;  // 0.1 s of the key at 3 cm/s
      },
      10s));
  EXPECT_EQ(in.right.source, surgery::PoseSource::hand);
  EXPECT_EQ(in.right.pedal, surgery::PedalMode::coag);
  EXPECT_EQ(in.left.pose.translation.x(), 0);
  keyboard->set_held(Control::right_x_plus, false);
  source.restart();
  ASSERT_TRUE(wait_for(
      [&] {
        in = source.next(s);
        return in.right.pose.translation.norm() < 1e-4;  // back at the start (tremor filter)
      },
      10s));
  source.stop();
}

// The numbers the metrics panel draws carry what the devices refused, by reason and by the
// sender's name, and the peers (nothing is refused in silence): a tracker sending under a
// name the scene does not map.
TEST(SimThread, TheNumbersCarryTheDevicesRefusalsByReasonAndName) {
  devices::IgtlDeviceConfig igtl;
  igtl.link.port = 0;
  auto device = std::make_unique<devices::IgtlDevice>(igtl);
  const std::uint16_t port = device->link().port();
  std::vector<std::unique_ptr<devices::InputDevice>> list;
  list.push_back(std::move(device));
  console::LiveConsoleParams params;
  params.loop.realtime_priority = 0;
  SimConfig config;
  config.realtime = false;
  config.end_s = 60;
  SimThread sim(config,
                std::make_unique<runner::ConsoleInputSource>(std::move(list), params, nullptr));
  sim.start();
  const test::LoopbackClient tracker(port);
  tracker.send(devices::encode_pose("Tracker", Pose{}, 1.0));
  LiveNumbers n;
  ASSERT_TRUE(wait_for([&] {
    return sim.latest_numbers(n) && n.has_device_tally && n.device_tally.counts.named == 1;
  }));
  sim.stop();
  const devices::DeviceCounts& c = n.device_tally.counts;
  EXPECT_EQ(c.refused_by_reason[std::size_t(devices::IgtlRefusal::unknown_device)], 1u);
  EXPECT_STREQ(c.refused_names[0].name.data(), "Tracker");
  EXPECT_EQ(c.refused_names[0].count, 1u);
  EXPECT_EQ(c.peers_seen, 1u);
  EXPECT_EQ(n.device_refusals, 1u);
}

}  // namespace
}  // namespace imasim::ui
