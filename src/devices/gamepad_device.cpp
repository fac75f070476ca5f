#include "devices/gamepad_device.hpp"

#include <SDL2/SDL.h>

#include <algorithm>
#include <cstdio>
#include <stdexcept>

namespace imasim::devices {

namespace {

// SDL is initialised once per process, its game-controller subsystem counted by SDL itself.
void start_sdl() {
  SDL_SetHint(SDL_HINT_JOYSTICK_ALLOW_BACKGROUND_EVENTS, "1");
  if (SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER) != 0)
    throw std::runtime_error(std::string("gamepad: SDL cannot start: ") + SDL_GetError());
}

Real axis(SDL_GameController* c, SDL_GameControllerAxis a) {
  return Real(SDL_GameControllerGetAxis(c, a)) / Real(32767);
}

}  // namespace

GamepadDevice::GamepadDevice(const GamepadMapping& mapping) : mapping_(mapping) {
  start_sdl();
  open_first();
}

GamepadDevice::~GamepadDevice() {
  if (controller_ != nullptr)
    SDL_GameControllerClose(static_cast<SDL_GameController*>(controller_));
  SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
}

void GamepadDevice::open_first() {
  for (int k = 0; k < SDL_NumJoysticks(); ++k) {
    if (!SDL_IsGameController(k)) continue;
    SDL_GameController* c = SDL_GameControllerOpen(k);
    if (c == nullptr) continue;
    controller_ = c;
    const char* name = SDL_GameControllerName(c);
    name_ = name != nullptr ? name : "game controller";
    return;
  }
}

void GamepadDevice::poll(double now_s, ConsoleInput& input) {
  SDL_GameControllerUpdate();
  auto* c = static_cast<SDL_GameController*>(controller_);
  if (c != nullptr && !SDL_GameControllerGetAttached(c)) {
    SDL_GameControllerClose(c);
    controller_ = c = nullptr;
    // A pad pulled out: no energy, the hands stop where they are.
    input.pedal = haptics::CauteryMode::off;
    input.left.velocity = input.right.velocity = Vec3::Zero();
  }
  if (c == nullptr) {
    open_first();  // plugged in since
    last_poll_s_ = now_s;
    return;
  }
  GamepadState pad;
  pad.axis[kLeftX] = axis(c, SDL_CONTROLLER_AXIS_LEFTX);
  pad.axis[kLeftY] = axis(c, SDL_CONTROLLER_AXIS_LEFTY);
  pad.axis[kRightX] = axis(c, SDL_CONTROLLER_AXIS_RIGHTX);
  pad.axis[kRightY] = axis(c, SDL_CONTROLLER_AXIS_RIGHTY);
  pad.axis[kLeftTrigger] = axis(c, SDL_CONTROLLER_AXIS_TRIGGERLEFT);
  pad.axis[kRightTrigger] = axis(c, SDL_CONTROLLER_AXIS_TRIGGERRIGHT);
  const SDL_GameControllerButton buttons[kGamepadButtons] = {SDL_CONTROLLER_BUTTON_A,
                                                             SDL_CONTROLLER_BUTTON_B,
                                                             SDL_CONTROLLER_BUTTON_X,
                                                             SDL_CONTROLLER_BUTTON_Y,
                                                             SDL_CONTROLLER_BUTTON_LEFTSHOULDER,
                                                             SDL_CONTROLLER_BUTTON_RIGHTSHOULDER};
  for (int b = 0; b < kGamepadButtons; ++b)
    pad.button[b] = SDL_GameControllerGetButton(c, buttons[b]) != 0;
  const Real dt = last_poll_s_ < 0 ? Real(0) : Real(std::clamp(now_s - last_poll_s_, 0.0, 0.05));
  last_poll_s_ = now_s;
  apply_gamepad(mapping_, pad, dt, input);
}

void GamepadDevice::send_force(Hand hand, const Vec3& force_n, double now_s) {
  force_[std::size_t(hand)] = force_n.allFinite() ? force_n.norm() : Real(0);
  auto* c = static_cast<SDL_GameController*>(controller_);
  // Rumble at 50 Hz, each lasting two periods: the larger force over a desktop device's 3.3 N.
  if (c == nullptr || now_s - last_rumble_s_ < 0.02) return;
  last_rumble_s_ = now_s;
  const Real level = std::clamp(std::max(force_[0], force_[1]) / Real(3.3), Real(0), Real(1));
  const auto strength = static_cast<Uint16>(level * 65535);
  SDL_GameControllerRumble(c, strength, strength, 40);
}

void GamepadDevice::polling_thread_ending() {
  SDL_TLSCleanup();  // SDL frees it only for threads it made itself
}

DeviceInfo GamepadDevice::info() const {
  DeviceInfo d;
  d.kind = "gamepad";
  d.name = controller_ != nullptr ? name_ : "no game controller found";
  char speed[32];
  std::snprintf(speed, sizeof speed, "%g", double(mapping_.speed));
  const GamepadMapping& m = mapping_;
  d.mapping = std::string("left / right stick -> left / right hand x, y (velocity, ") + speed +
              " m/s at full deflection; shoulder held: y moves z)\n"
              "left / right trigger -> left / right jaw (pulled = closed)\n" +
              gamepad_button_name(m.cut_button) + " -> pedal cut, " +
              gamepad_button_name(m.coag_button) + " -> pedal coag (while held)\n" +
              gamepad_button_name(m.clutch_button[0]) + " / " +
              gamepad_button_name(m.clutch_button[1]) +
              " -> left / right clutch (while held)\nforces -> rumble";
  d.connected = controller_ != nullptr;
  d.force_feedback = false;
  d.workspace_m = Vec3::Constant(2 * mapping_.reach);
  d.drives_left = d.drives_right = d.drives_pedal = true;
  return d;
}

std::vector<std::string> GamepadDevice::list_controllers() {
  std::vector<std::string> out;
  if (SDL_InitSubSystem(SDL_INIT_GAMECONTROLLER) != 0) return out;
  for (int k = 0; k < SDL_NumJoysticks(); ++k) {
    const char* name =
        SDL_IsGameController(k) ? SDL_GameControllerNameForIndex(k) : SDL_JoystickNameForIndex(k);
    out.push_back(std::string(SDL_IsGameController(k) ? "game controller: " : "joystick: ") +
                  (name != nullptr ? name : "unnamed"));
  }
  SDL_QuitSubSystem(SDL_INIT_GAMECONTROLLER);
  return out;
}

}  // namespace imasim::devices
