#include "ui/key_bindings.hpp"

// The key codes only: no OpenGL header (the window's files include libepoxy's first).
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <array>

namespace imasim::ui {

namespace {

constexpr KeyBinding control(int key, const char* name, Control c, const char* meaning) {
  return {key, name, true, c, Command::none, meaning};
}
constexpr KeyBinding command(int key, const char* name, Command c, const char* meaning) {
  return {key, name, false, Control::count, c, meaning};
}

// Left hand on the left of the keyboard, right hand on the right; window commands on function
// keys so that no letter does two things.
constexpr std::array kBindings = {
    control(GLFW_KEY_A, "A", Control::left_x_minus, "left hand: left"),
    control(GLFW_KEY_D, "D", Control::left_x_plus, "left hand: right"),
    control(GLFW_KEY_S, "S", Control::left_y_minus, "left hand: nearer"),
    control(GLFW_KEY_W, "W", Control::left_y_plus, "left hand: away"),
    control(GLFW_KEY_Q, "Q", Control::left_z_minus, "left hand: down"),
    control(GLFW_KEY_E, "E", Control::left_z_plus, "left hand: up"),
    control(GLFW_KEY_R, "R", Control::left_jaw_close, "left jaws (forceps): close while held"),
    control(GLFW_KEY_F, "F", Control::left_jaw_open, "left jaws (forceps): open while held"),
    control(GLFW_KEY_C, "C", Control::left_clutch, "left clutch (held: hand moves alone)"),
    control(GLFW_KEY_J, "J", Control::right_x_minus, "right hand: left"),
    control(GLFW_KEY_L, "L", Control::right_x_plus, "right hand: right"),
    control(GLFW_KEY_K, "K", Control::right_y_minus, "right hand: nearer"),
    control(GLFW_KEY_I, "I", Control::right_y_plus, "right hand: away"),
    control(GLFW_KEY_U, "U", Control::right_z_minus, "right hand: down"),
    control(GLFW_KEY_O, "O", Control::right_z_plus, "right hand: up"),
    control(GLFW_KEY_P, "P", Control::right_jaw_close, "right jaws (hook): close while held"),
    control(GLFW_KEY_SEMICOLON, ";", Control::right_jaw_open, "right jaws (hook): open while held"),
    control(GLFW_KEY_M, "M", Control::right_clutch, "right clutch (held: hand moves alone)"),
    control(GLFW_KEY_1, "1", Control::pedal_cut, "pedal: cut (held)"),
    control(GLFW_KEY_2, "2", Control::pedal_coag, "pedal: coagulation (held)"),
    command(GLFW_KEY_EQUAL, "=", Command::power_up, "cautery power +5 W"),
    command(GLFW_KEY_MINUS, "-", Command::power_down, "cautery power -5 W"),
    command(GLFW_KEY_SPACE, "Space", Command::pause, "pause / resume"),
    command(GLFW_KEY_F1, "F1", Command::help, "show / hide this help"),
    command(GLFW_KEY_TAB, "Tab", Command::panels, "show / hide the panels"),
    command(GLFW_KEY_F2, "F2", Command::camera, "endoscope / orbit camera"),
    command(GLFW_KEY_F3, "F3", Command::optics, "endoscope optics 0 / 30 degrees"),
    command(GLFW_KEY_F4, "F4", Command::stereo, "stereo: off / side by side / anaglyph"),
    command(GLFW_KEY_F5, "F5", Command::restart, "restart the session"),
    command(GLFW_KEY_F6, "F6", Command::heart, "dynamic / static heart (restarts)"),
    command(GLFW_KEY_F8, "F8", Command::record, "record on / off"),
    command(GLFW_KEY_F10, "F10", Command::end_session, "end the session: score card"),
    command(GLFW_KEY_ESCAPE, "Escape", Command::quit, "quit"),
};

}  // namespace

std::span<const KeyBinding> key_bindings() {
  return kBindings;
}

const KeyBinding* binding_for(int key) {
  for (const KeyBinding& b : kBindings)
    if (b.key == key) return &b;
  return nullptr;
}

std::string bindings_text() {
  std::string text;
  for (const KeyBinding& b : kBindings)
    text += std::string(b.key_name) + "\t" + b.meaning + "\n";
  text +=
      "mouse\tleft drag: orbit the camera, wheel: zoom; right drag: right hand (Shift: depth), "
      "middle drag: left hand\n";
  return text;
}

}  // namespace imasim::ui
