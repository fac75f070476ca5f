#include "devices/joystick_pedal_device.hpp"

#include <SDL2/SDL.h>

#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace imasim::devices {

namespace {

void start_sdl_joysticks() {
  SDL_SetHint(SDL_HINT_JOYSTICK_ALLOW_BACKGROUND_EVENTS, "1");
  if (SDL_InitSubSystem(SDL_INIT_JOYSTICK) != 0)
    throw std::runtime_error(std::string("pedals: SDL cannot start: ") + SDL_GetError());
}

std::string lower(std::string s) {
  for (char& c : s)
    c = char(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string button_name(std::uint32_t b) {
  return b == kNoPedalButton ? std::string("none") : "button " + std::to_string(b);
}

}  // namespace

bool joystick_name_matches(const std::string& pattern, const std::string& name,
                           bool is_game_controller) {
  if (pattern == "any") return !is_game_controller;
  return lower(name).find(lower(pattern)) != std::string::npos;
}

JoystickPedalDevice::JoystickPedalDevice(const PedalMapping& mapping) : mapping_(mapping) {
  start_sdl_joysticks();
  open_matching();
}

JoystickPedalDevice::~JoystickPedalDevice() {
  if (joystick_ != nullptr) SDL_JoystickClose(static_cast<SDL_Joystick*>(joystick_));
  SDL_QuitSubSystem(SDL_INIT_JOYSTICK);
}

void JoystickPedalDevice::open_matching() {
  for (int k = 0; k < SDL_NumJoysticks(); ++k) {
    const char* name = SDL_JoystickNameForIndex(k);
    const std::string n = name != nullptr ? name : "";
    if (!joystick_name_matches(mapping_.joystick, n, SDL_IsGameController(k) == SDL_TRUE)) continue;
    SDL_Joystick* j = SDL_JoystickOpen(k);
    if (j == nullptr) continue;
    joystick_ = j;
    name_ = n.empty() ? "joystick" : n;
    return;
  }
}

void JoystickPedalDevice::poll(double, ConsoleInput& input) {
  SDL_JoystickUpdate();
  auto* j = static_cast<SDL_Joystick*>(joystick_);
  if (j != nullptr && !SDL_JoystickGetAttached(j)) {
    SDL_JoystickClose(j);
    joystick_ = j = nullptr;
    release_pedals(mapping_, input);  // a foot switch pulled out is a foot lifted
  }
  if (j == nullptr) {
    open_matching();  // plugged in since
    return;
  }
  const int count = std::min(SDL_JoystickNumButtons(j), int(held_.size()));
  held_.fill(false);
  for (int b = 0; b < count; ++b)
    held_[std::size_t(b)] = SDL_JoystickGetButton(j, b) != 0;
  apply_pedals(mapping_, held_, input);
}

void JoystickPedalDevice::polling_thread_ending() {
  SDL_TLSCleanup();  // SDL frees it only for threads it made itself
}

DeviceInfo JoystickPedalDevice::info() const {
  DeviceInfo d;
  d.kind = "pedal";
  d.name = joystick_ != nullptr ? name_ : "no joystick matching \"" + mapping_.joystick + "\"";
  d.mapping = button_name(mapping_.cut_button) + " -> pedal cut (while held)\n" +
              button_name(mapping_.coag_button) + " -> pedal coag (while held)\n" +
              button_name(mapping_.clutch_button) + " -> both clutches (while held)";
  d.connected = joystick_ != nullptr;
  d.drives_pedal = true;
  return d;
}

}  // namespace imasim::devices
