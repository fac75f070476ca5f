#pragma once
// A virtual SDL joystick for tests (no hardware, no display): a game controller's axes and
// buttons, or a plain HID joystick's buttons (as foot switches are), attached while the object
// lives or until unplug().
#include <SDL2/SDL.h>

namespace imasim::test {

class VirtualJoystick {
 public:
  // `controller`: a game controller (SDL's full set of axes and buttons); otherwise a plain
  // joystick with `buttons` buttons and no axes.
  VirtualJoystick(const char* name, bool controller, int buttons = 0)
      : subsystem_(controller ? SDL_INIT_GAMECONTROLLER : SDL_INIT_JOYSTICK) {
    SDL_SetHint(SDL_HINT_JOYSTICK_ALLOW_BACKGROUND_EVENTS, "1");
    if (SDL_InitSubSystem(subsystem_) != 0) return;
    initialised_ = true;
    SDL_VirtualJoystickDesc desc{};
    desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
    desc.type = controller ? SDL_JOYSTICK_TYPE_GAMECONTROLLER : SDL_JOYSTICK_TYPE_UNKNOWN;
    desc.naxes = controller ? Uint16(SDL_CONTROLLER_AXIS_MAX) : Uint16(0);
    desc.nbuttons = controller ? Uint16(SDL_CONTROLLER_BUTTON_MAX) : Uint16(buttons);
    desc.name = name;
    index_ = SDL_JoystickAttachVirtualEx(&desc);
    stick_ = index_ >= 0 ? SDL_JoystickOpen(index_) : nullptr;
  }
  ~VirtualJoystick() {
    unplug();
    if (initialised_) SDL_QuitSubSystem(subsystem_);
  }
  VirtualJoystick(const VirtualJoystick&) = delete;
  VirtualJoystick& operator=(const VirtualJoystick&) = delete;

  bool attached() const { return stick_ != nullptr; }
  void set_axis(int axis, Sint16 value) { SDL_JoystickSetVirtualAxis(stick_, axis, value); }
  void set_button(int button, bool down) {
    SDL_JoystickSetVirtualButton(stick_, button, down ? 1 : 0);
  }
  // Pulled out: devices reading it see it gone.
  void unplug() {
    if (stick_) SDL_JoystickClose(stick_);
    if (index_ >= 0) SDL_JoystickDetachVirtual(index_);
    stick_ = nullptr;
    index_ = -1;
  }

 private:
  Uint32 subsystem_;
  bool initialised_ = false;
  int index_ = -1;
  SDL_Joystick* stick_ = nullptr;
};

}  // namespace imasim::test
