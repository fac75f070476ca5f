#pragma once
// Where a session's steps take their input from: one interface for every driver of a session
// (SessionRunner, session_runner.hpp). Implementations: the input script sampled at the session's
// time, a recorded stream played a line a step, no one at the console and the input its owner
// sets (the Python module's; here), the live console with its devices and
// 1 kHz haptic loop (ConsoleInputSource, here; the command line's LiveInputs, which also starts
// an emulator), the scripted operator (the command line's RunAutopilot).
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "console/live_console.hpp"
#include "session/surgical_session.hpp"
#include "surgery/input_script.hpp"

namespace imasim::runner {

class InputSource {
 public:
  virtual ~InputSource() = default;
  // The input of the coming step.
  virtual session::SessionInput next(const session::SurgicalSession& session) = 0;
  // After step number `step` (1 for the first) of the current session: e.g. the live console
  // publishes the haptic loop's local models.
  virtual void after_step(const session::SurgicalSession&, std::uint64_t /*step*/) {}
  // A new session starts (hands back at their start).
  virtual void restart() {}
  // Stops any thread of its own (safe twice).
  virtual void stop() {}
  // How many steps it can give from the start, when it ends (a recorded stream); none: as many
  // as asked.
  virtual std::optional<std::uint64_t> length() const { return {}; }
  // After stop(): the live console's figures (its 1 kHz loop's timing), when there is one.
  virtual std::optional<console::LiveConsoleStats> console_stats() const { return {}; }
  // Any thread: the device messages refused so far (0 without a live console).
  virtual std::uint64_t refused_total() const { return 0; }
  // The devices' refusals, peers and losses (empty without a live console).
  virtual std::optional<console::DeviceTally> device_tally() { return {}; }
};

// No one at the console: the instruments stay where they are (a scene watched, not operated).
class IdleInput final : public InputSource {
 public:
  session::SessionInput next(const session::SurgicalSession&) override { return {}; }
};

// The input its owner sets between steps (the Python module's Session and HarvestEnv): every
// step takes the input last set, as a device's newest reading would be.
class CommandedInput final : public InputSource {
 public:
  session::SessionInput next(const session::SurgicalSession&) override { return input; }
  session::SessionInput input;
};

// The input script, sampled at the session's simulated time (session::sample_script).
class ScriptInput final : public InputSource {
 public:
  explicit ScriptInput(surgery::InputScript script) : script_(std::move(script)) {}
  session::SessionInput next(const session::SurgicalSession& session) override;
  const surgery::InputScript& script() const { return script_; }

 private:
  surgery::InputScript script_;
};

// A recorded input stream (console/input_stream.hpp), one line a step from the session's start.
class ReplayInput final : public InputSource {
 public:
  explicit ReplayInput(std::vector<session::SessionInput> steps) : steps_(std::move(steps)) {}
  // Past the stream's end: the hands let go, as a stream that stopped would leave them.
  session::SessionInput next(const session::SurgicalSession& session) override;
  void restart() override { next_ = 0; }
  std::optional<std::uint64_t> length() const override { return steps_.size(); }

 private:
  std::vector<session::SessionInput> steps_;
  std::size_t next_ = 0;
};

// The live console: devices polled by its 1 kHz haptic loop, which renders eq. 17-19 from the
// local models published after each step.
class ConsoleInputSource final : public InputSource {
 public:
  // Starts the console's 1 kHz loop. `on_restart` (may be empty) runs when a session restarts
  // (the window's keyboard puts its hands back).
  ConsoleInputSource(std::vector<std::unique_ptr<devices::InputDevice>> devices,
                     const console::LiveConsoleParams& params, std::function<void()> on_restart);
  ~ConsoleInputSource() override;
  session::SessionInput next(const session::SurgicalSession& session) override;
  void after_step(const session::SurgicalSession& session, std::uint64_t step) override;
  void restart() override;
  void stop() override;
  std::optional<console::LiveConsoleStats> console_stats() const override {
    return console_.stats();
  }
  std::uint64_t refused_total() const override { return console_.refused_total(); }
  std::optional<console::DeviceTally> device_tally() override { return console_.device_tally(); }

 private:
  std::function<void()> on_restart_;
  console::LiveConsole console_;
  std::uint64_t published_ = 0;  // steps published over all sessions: the loop's step ids
};

}  // namespace imasim::runner
