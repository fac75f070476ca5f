#pragma once
// The physics thread of the window: owns the surgical session and steps it through the
// session runner (runner/session_runner.hpp) in real time at its dt (5 ms) with the input
// source's input; after every third step (about 60 Hz)
// fills a RenderFrame and the live numbers and publishes them lock-free, so drawing never
// blocks physics. The window's commands (pause, restart, heart mode, record, end) come the
// other way through atomics, read once per step.
#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

#include "base/latest_value.hpp"
#include "physics/executor.hpp"
#include "render/render_frame.hpp"
#include "runner/input_source.hpp"
#include "runner/session_runner.hpp"
#include "scene/thorax_scene.hpp"
#include "session/surgical_session.hpp"
#include "ui/live_numbers.hpp"
#include "ui/session_score.hpp"

namespace imasim::ui {

struct SimConfig {
  scene::ThoraxSceneParams scene = scene::default_thorax_scene_params();
  session::SessionParams session;
  std::string scene_name = "built-in thorax";  // for recordings
  int threads = 1;                             // the solver's (0: all cores)
  double end_s = 0;         // simulated time at which the session ends (0: never; unit: s)
  bool realtime = true;     // false: as fast as the machine steps (tests)
  int steps_per_frame = 3;  // 5 ms steps: a frame every 15 ms
  std::string record_path;  // "": imasim-window.csv in the working directory
};

class SimThread final : private runner::StepObserver {
 public:
  // Builds the first session on the calling thread: throws what make_surgical_session throws
  // (a scene that cannot be built is reported before any window opens).
  SimThread(const SimConfig& config, std::unique_ptr<runner::InputSource> input);
  ~SimThread() override;
  SimThread(const SimThread&) = delete;
  SimThread& operator=(const SimThread&) = delete;

  void start();
  void stop();  // joins the thread and stops the input source; safe twice

  // Window thread: commands, taken at the next step.
  void set_paused(bool paused) { paused_.store(paused); }
  bool paused() const { return paused_.load(); }
  void restart() { restart_.store(true); }
  void set_beating(bool beating) { beating_next_.store(beating); }  // from the next restart
  void set_recording(bool on) { record_.store(on); }
  void end_session() { end_.store(true); }
  // The endoscope's optics (unit: rad); negative: the input's (a script's camera track).
  void set_optics(float optics_rad) { optics_.store(optics_rad); }

  // Window thread: the newest frame (null before the first; valid until the next call).
  const render::RenderFrame* latest_frame(bool* fresh = nullptr) { return frames_.latest(fresh); }
  // Window thread: the newest numbers; false before the first.
  bool latest_numbers(LiveNumbers& out) { return numbers_.read(out); }
  // Window thread: the score card of the session that ended last; its generation counts the
  // cards (0: none yet), so a caller copies it only when it changes.
  std::uint64_t score_card_generation() const { return card_generation_.load(); }
  std::optional<ScoreCard> score_card() const;
  // After stop(): the live console's figures, when the input is one.
  std::optional<console::LiveConsoleStats> console_stats() const {
    return input_ ? input_->console_stats() : std::nullopt;
  }
  // The session reached its end time (or was ended) at least once: the card is ready.
  bool finished() const { return card_generation_.load() > 0; }

 private:
  void run();
  void build_session();
  void step_once();
  std::uint64_t steps() const { return runner_ ? runner_->steps_done() : 0; }
  // After each step the runner takes: the score's sample and, every few steps, the frame.
  void after_step(const session::SurgicalSession& session,
                  const runner::StepRecord& record) override;
  void finish_session(const char* why);
  void publish(bool frame);
  void take_commands();
  void note(const std::string& text);
  std::string next_record_path();

  SimConfig config_;
  std::unique_ptr<runner::InputSource> input_;
  physics::Executor exec_;
  std::unique_ptr<session::SurgicalSession> session_;
  std::unique_ptr<runner::SessionRunner> runner_;  // steps session_ (null while there is none)
  std::unique_ptr<SessionScore> score_;
  SimState state_ = SimState::starting;
  LiveNumbers numbers_out_;  // physics thread's copy, published whole
  double last_step_ms_ = 0;
  std::size_t events_tallied_ = 0;  // of the session's events, counted into numbers_out_
  std::chrono::steady_clock::time_point born_ = std::chrono::steady_clock::now();
  double rate_wall_s_ = 0, rate_sim_s_ = 0;  // where the realtime factor was measured last
  int recordings_ = 0;

  base::LatestValue<render::RenderFrame> frames_;
  base::LatestValue<LiveNumbers> numbers_;
  mutable std::mutex card_mutex_;  // the card is made once a session; never on the step path
  std::optional<ScoreCard> card_;
  std::atomic<std::uint64_t> card_generation_{0};

  std::atomic<bool> quit_{false}, paused_{false}, restart_{false}, end_{false}, record_{false};
  std::atomic<bool> beating_next_{true};
  std::atomic<float> optics_{-1};
  std::thread thread_;
  bool stopped_ = false;
};

}  // namespace imasim::ui
