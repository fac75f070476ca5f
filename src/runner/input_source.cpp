#include "runner/input_source.hpp"

#include "console/console_mapping.hpp"

namespace imasim::runner {

session::SessionInput ScriptInput::next(const session::SurgicalSession& s) {
  return session::sample_script(script_, s.scene.patch.world.state.time);
}

session::SessionInput ReplayInput::next(const session::SurgicalSession&) {
  if (next_ >= steps_.size()) return session::SessionInput{};
  return steps_[next_++];
}

ConsoleInputSource::ConsoleInputSource(std::vector<std::unique_ptr<devices::InputDevice>> devices,
                                       const console::LiveConsoleParams& params,
                                       std::function<void()> on_restart)
    : on_restart_(std::move(on_restart)), console_(std::move(devices), params) {
  console_.start();
}

ConsoleInputSource::~ConsoleInputSource() {
  stop();
}

session::SessionInput ConsoleInputSource::next(const session::SurgicalSession& s) {
  return console::to_session_input(console_.latest_input(), s);
}

void ConsoleInputSource::after_step(const session::SurgicalSession& s, std::uint64_t) {
  // The loop tells a new model by its step number: keep it rising across restarts.
  console_.publish(s, ++published_);
}

void ConsoleInputSource::restart() {
  if (on_restart_) on_restart_();
}

void ConsoleInputSource::stop() {
  console_.stop();
}

}  // namespace imasim::runner
