#pragma once
// Which key does what in the window: the console's controls (hands, jaws, clutches,
// pedal, power) and the window's commands, in one table that the key handler, the keyboard
// device's description and the help panel all read. Keys are GLFW key codes (US layout
// positions, whatever the keyboard's letters).
#include <cstdint>
#include <span>
#include <string>

#include "ui/keyboard_mouse_device.hpp"

namespace imasim::ui {

// What the window does on a key press (the console's controls aside).
enum class Command : std::uint8_t {
  none,
  quit,
  pause,        // pause or resume
  camera,       // endoscope <-> orbit camera
  optics,       // the endoscope's 0 <-> 30 degree optics
  stereo,       // off -> side by side -> anaglyph -> off
  restart,      // a new session
  heart,        // dynamic <-> static heart (takes effect at the restart it triggers)
  record,       // start or stop recording
  end_session,  // stop the session and show its score card
  help,         // show or hide the help panel
  panels,       // show or hide the panels' column
  power_up,
  power_down,
};

struct KeyBinding {
  int key = 0;  // GLFW_KEY_...
  const char* key_name = "";
  bool is_control = false;  // true: `control`, held; false: `command`, on press
  Control control = Control::count;
  Command command = Command::none;
  const char* meaning = "";
};

std::span<const KeyBinding> key_bindings();
// The binding of a GLFW key, or null.
const KeyBinding* binding_for(int key);
// One line a binding ("W / S   left hand away / nearer"), for the help panel and the device.
std::string bindings_text();

}  // namespace imasim::ui
