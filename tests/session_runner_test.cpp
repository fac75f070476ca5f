// The one session loop (runner/session_runner.hpp): the same steps as stepping the session by
// hand, its observers in order, its input's end, a stop, an output error, real-time pacing, and
// the recorded input stream replaying to the same state.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "console/input_stream.hpp"
#include "console/stream_origin.hpp"
#include "metrics/output_file.hpp"
#include "physics/state.hpp"
#include "runner/input_source.hpp"
#include "runner/input_stream_recorder.hpp"
#include "runner/session_runner.hpp"
#include "surgery/input_script.hpp"

namespace imasim::runner {
namespace {

using session::SessionInput;
using session::SurgicalSession;

SurgicalSession fresh_session() {
  return session::make_surgical_session(scene::default_thorax_scene_params(),
                                        session::SessionParams{});
}

surgery::InputScript example_script() {
  return surgery::load_input_script(std::string(IMASIM_SOURCE_DIR) +
                                    "/examples/open_fascia.script");
}

// Records what it is shown, in order, into a shared log.
class Logger final : public StepObserver {
 public:
  Logger(char name, std::vector<std::string>& log) : name_(name), log_(log) {}
  void before_step(const SurgicalSession&, const SessionInput&, std::uint64_t step) override {
    log_.push_back(std::string(1, name_) + " before " + std::to_string(step));
  }
  void after_step(const SurgicalSession&, const StepRecord& r) override {
    log_.push_back(std::string(1, name_) + " after " + std::to_string(r.step));
    EXPECT_TRUE(r.result.ok());
    EXPECT_GE(r.step_ms, 0);
  }
  void finish(const SurgicalSession&) override {
    log_.push_back(std::string(1, name_) + " finish");
  }

 private:
  char name_;
  std::vector<std::string>& log_;
};

// Fails to write after step `fail_at` (or before it, with `before`).
class FailingWriter final : public StepObserver {
 public:
  FailingWriter(std::uint64_t fail_at, bool before) : fail_at_(fail_at), before_(before) {}
  void before_step(const SurgicalSession&, const SessionInput&, std::uint64_t step) override {
    if (before_ && step == fail_at_) throw metrics::OutputError("disk full before");
  }
  void after_step(const SurgicalSession&, const StepRecord& r) override {
    if (!before_ && r.step == fail_at_) throw metrics::OutputError("disk full after");
  }
  int finished = 0;
  void finish(const SurgicalSession&) override { ++finished; }

 private:
  std::uint64_t fail_at_;
  bool before_;
};

TEST(SessionRunner, StepsTheSessionAsStepByStepSamplingOfTheScriptDoes) {
  const surgery::InputScript script = example_script();
  constexpr std::uint64_t kSteps = 120;
  SurgicalSession by_hand = fresh_session();
  physics::Executor exec(1);
  for (std::uint64_t k = 0; k < kSteps; ++k) {
    const SessionInput in = session::sample_script(script, by_hand.scene.patch.world.state.time);
    ASSERT_TRUE(session::step_session(by_hand, in, exec).ok());
  }
  SurgicalSession run = fresh_session();
  ScriptInput input(script);
  SessionRunner runner(run, input, exec);
  const RunOutcome out = runner.run(kSteps);
  EXPECT_EQ(out.steps, kSteps);
  EXPECT_TRUE(out.failure.ok());
  EXPECT_TRUE(out.output_error.empty());
  EXPECT_EQ(physics::position_hash(run.scene.patch.world.state),
            physics::position_hash(by_hand.scene.patch.world.state));
}

TEST(SessionRunner, ShowsEachStepToItsObserversInOrderAndTellsThemTheEnd) {
  SurgicalSession s = fresh_session();
  physics::Executor exec(1);
  IdleInput idle;
  SessionRunner runner(s, idle, exec);
  std::vector<std::string> log;
  Logger a('a', log), b('b', log);
  runner.observe(a);
  runner.observe(b);
  EXPECT_EQ(runner.run(2).steps, 2u);
  const std::vector<std::string> expected = {"a before 0", "b before 0", "a after 1", "b after 1",
                                             "a before 1", "b before 1", "a after 2", "b after 2",
                                             "a finish",   "b finish"};
  EXPECT_EQ(log, expected);
  EXPECT_EQ(runner.steps_done(), 2u);
}

TEST(SessionRunner, ARecordedStreamEndsTheRunAtItsLastStep) {
  SurgicalSession s = fresh_session();
  physics::Executor exec(1);
  ReplayInput replay(std::vector<SessionInput>(7));
  SessionRunner runner(s, replay, exec);
  EXPECT_EQ(runner.run(100).steps, 7u);
  EXPECT_NEAR(double(s.scene.patch.world.state.time),
              7 * double(s.scene.patch.world.model.solver.dt), 1e-12);
}

TEST(SessionRunner, StopsWhenAskedBeforeTheNextStep) {
  SurgicalSession s = fresh_session();
  physics::Executor exec(1);
  IdleInput idle;
  SessionRunner runner(s, idle, exec);
  const RunOutcome out = runner.run(100, [&] { return runner.steps_done() >= 3; });
  EXPECT_TRUE(out.stopped);
  EXPECT_EQ(out.steps, 3u);
}

TEST(SessionRunner, AnObserverThatCannotWriteStopsTheRunAndTheOthersStillFinish) {
  for (const bool before : {false, true}) {
    SCOPED_TRACE(before ? "before the step" : "after the step");
    SurgicalSession s = fresh_session();
    physics::Executor exec(1);
    IdleInput idle;
    SessionRunner runner(s, idle, exec);
    FailingWriter failing(4, before);
    std::vector<std::string> log;
    Logger other('o', log);
    runner.observe(failing);
    runner.observe(other);
    const RunOutcome out = runner.run(10);
    // After the fourth step: it was taken and the run stops there. Before the fifth (its index
    // is 4): it is not taken. Four steps either way.
    EXPECT_EQ(out.steps, 4u);
    EXPECT_EQ(out.output_error, before ? "disk full before" : "disk full after");
    EXPECT_EQ(failing.finished, 1);
    ASSERT_FALSE(log.empty());
    EXPECT_EQ(log.back(), "o finish");
    EXPECT_EQ(runner.steps_done(), 4u);
  }
}

TEST(SessionRunner, RealTimePacingTakesAtLeastTheSimulatedTime) {
  SurgicalSession s = fresh_session();
  physics::Executor exec(1);
  IdleInput idle;
  SessionRunner runner(s, idle, exec, Pacing::real_time);
  const double dt = double(s.scene.patch.world.model.solver.dt);
  const auto t0 = std::chrono::steady_clock::now();
  EXPECT_EQ(runner.run(20).steps, 20u);
  const double took = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  // Step k is due k dt after the first began: the twentieth no sooner than 20 dt.
  EXPECT_GE(took, 20 * dt);
}

TEST(SessionRunner, TheRecordedInputStreamReplaysToTheSameState) {
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / "imasim_session_runner_test";
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "stream.txt").string();
  physics::Executor exec(1);
  constexpr std::uint64_t kSteps = 80;
  SurgicalSession recorded = fresh_session();
  {
    ScriptInput input(example_script());
    SessionRunner runner(recorded, input, exec);
    InputStreamRecorder recorder(
        metrics::OutputFile(path, "the input stream"),
        console::stream_origin_of(scene::default_thorax_scene_params(), "0.0-test"));
    runner.observe(recorder);
    ASSERT_EQ(runner.run(kSteps).steps, kSteps);
    EXPECT_EQ(recorder.lines(), kSteps);
  }
  console::RecordedStream stream = console::load_recorded_stream(path);
  ASSERT_EQ(stream.steps.size(), kSteps);
  SurgicalSession replayed = fresh_session();
  ReplayInput replay(std::move(stream.steps));
  SessionRunner runner(replayed, replay, exec);
  EXPECT_EQ(runner.run(kSteps + 50).steps, kSteps);
  EXPECT_EQ(physics::position_hash(replayed.scene.patch.world.state),
            physics::position_hash(recorded.scene.patch.world.state));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace imasim::runner
