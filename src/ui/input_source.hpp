#pragma once
// Where the window's session takes each step's input from: an input script sampled at the
// step's simulated time, or the live console (the keyboard and mouse, plus any device of
// `imasim run --devices`) whose 1 kHz loop runs on its own thread and renders the forces.
#include <memory>
#include <optional>
#include <vector>

#include "console/live_console.hpp"
#include "session/surgical_session.hpp"
#include "surgery/input_script.hpp"
#include "ui/keyboard_mouse_device.hpp"

namespace imasim::ui {

class InputSource {
 public:
  virtual ~InputSource() = default;
  // Physics thread: the input of the coming step.
  virtual session::SessionInput next(const session::SurgicalSession& session) = 0;
  // Physics thread: after step number `step` (1 for the first) of the current session.
  virtual void after_step(const session::SurgicalSession& session, std::uint64_t step) = 0;
  // Physics thread: a new session starts (hands back at their start).
  virtual void restart() = 0;
  // Stops any thread of its own (safe twice).
  virtual void stop() = 0;
  // After stop(): the live console's figures (its 1 kHz loop's timing), when there is one.
  virtual std::optional<console::LiveConsoleStats> console_stats() const { return {}; }
  // Any thread: the device messages refused so far (0 without a live console).
  virtual std::uint64_t refused_total() const { return 0; }
  // Physics thread: the devices' refusals, peers and losses (empty without a live console).
  virtual std::optional<console::DeviceTally> device_tally() { return {}; }
};

class ScriptInput final : public InputSource {
 public:
  explicit ScriptInput(surgery::InputScript script) : script_(std::move(script)) {}
  session::SessionInput next(const session::SurgicalSession& session) override;
  void after_step(const session::SurgicalSession&, std::uint64_t) override {}
  void restart() override {}
  void stop() override {}

 private:
  surgery::InputScript script_;
};

class ConsoleInputSource final : public InputSource {
 public:
  // `keyboard` (may be null) is one of `devices`, reset when a session restarts. Starts the
  // console's 1 kHz loop.
  ConsoleInputSource(std::vector<std::unique_ptr<devices::InputDevice>> devices,
                     KeyboardMouseDevice* keyboard, const console::LiveConsoleParams& params);
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
  KeyboardMouseDevice* keyboard_;
  console::LiveConsole console_;
  std::uint64_t published_ = 0;  // steps published over all sessions: the loop's step ids
};

}  // namespace imasim::ui
