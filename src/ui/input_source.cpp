#include "ui/input_source.hpp"

#include "console/console_mapping.hpp"

namespace imasim::ui {

session::SessionInput ScriptInput::next(const session::SurgicalSession& s) {
  return session::sample_script(script_, s.scene.patch.world.state.time);
}

ConsoleInputSource::ConsoleInputSource(std::vector<std::unique_ptr<devices::InputDevice>> devices,
                                       KeyboardMouseDevice* keyboard,
                                       const console::LiveConsoleParams& params)
    : keyboard_(keyboard), console_(std::move(devices), params) {
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
  if (keyboard_) keyboard_->reset();
}

void ConsoleInputSource::stop() {
  console_.stop();
}

}  // namespace imasim::ui
