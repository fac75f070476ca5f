#pragma once
// The console's input as the session's: a device's hands and pedal become the two
// instruments' inputs. A hand pose goes through the arm (motion scaling, clutch, port); a tool
// pose (a tracker on the instrument) places the hinge directly. A device's jaw (0 open .. 1
// closed) is a target angle, (1 - jaw) theta_max, which the jaws reach at their button rate
// (eq. 16); the pedal drives the cautery hook (right hand).
#include "devices/hand_input.hpp"
#include "session/surgical_session.hpp"

namespace imasim::console {

// Jaw targets within this of the current angle hold (unit: rad).
inline constexpr Real kJawDeadband = Real(0.01);

session::SessionInput to_session_input(const devices::ConsoleInput& console,
                                       const session::SurgicalSession& session);

}  // namespace imasim::console
