#pragma once
// Kinematics of a surgical instrument (paper 2.4.3, eq. 14-16; SPEC S4). The configuration is
// a pose in SE(3) and the angles of two jaws (eq. 14); the pose follows the transform chain
// T_world = T_controller * T_local * T_initial (eq. 15); the jaw angle integrates the rate the
// buttons ask for, theta(t + dt) = theta(t) + theta_dot dt (eq. 16), clamped to its range; the
// jaws turn symmetrically about the hinge axis alpha, T_upper = R(theta, alpha), T_lower =
// R(-theta, alpha); they count as closed below 2.86 degrees.
//
// Tool frame (as in eq. 10): f = R (0, 0, 1) points along the shaft towards the tip, l = R (1,
// 0, 0) along the hinge axis, n = R (0, 1, 0) the jaws' opening direction. The frame's origin
// is the jaws' hinge (the wrist's end). alpha = -l: a positive turn about alpha takes f towards
// alpha x f = n, so the upper jaw opens towards +n (its tip at n = +length sin theta) and the
// lower towards -n; about +l the upper jaw would open towards -n.
#include <cstdint>

#include "math/angles.hpp"
#include "math/pose.hpp"

namespace imasim::surgery {

enum class InstrumentKind : std::uint8_t { forceps, cautery_hook, cautery_spatula };

// Reading of eq. 14 for a symmetric instrument: the upper jaw at +theta, the lower at -theta,
// each in [-theta_max, theta_max]; theta < 0 would cross the jaws, so theta is in [0, theta_max].
struct JawParams {
  Real max_angle = degrees_to_radians(Real(30));           // theta_max (Fig. 11a) (unit: rad)
  Real closed_threshold = degrees_to_radians(Real(2.86));  // closed below this (unit: rad)
  Real button_rate = degrees_to_radians(Real(120));  // |theta_dot| while a button is held (rad/s)
  Vec3 hinge_axis = -Vec3::UnitX();  // alpha, in the tool frame: -l, so the upper jaw opens to +n
  Real length = Real(0.012);         // hinge to jaw tip (unit: m)
  Real width = Real(0.003);          // across the hinge axis (unit: m)
};

struct InstrumentParams {
  InstrumentKind kind = InstrumentKind::forceps;
  Pose initial;  // T_initial: the tool model's offset in its own frame
  JawParams jaws;
  Real shaft_radius = Real(0.004);  // 8 mm robotic instruments (unit: m)
  Real shaft_length = Real(0.35);   // (unit: m)
};

// What the buttons ask of the jaws.
enum class JawCommand : std::int8_t { close = -1, hold = 0, open = 1 };

struct InstrumentState {
  Pose controller;  // T_controller: from the arm (robotic_arm.hpp) or a device
  Pose local;       // T_local: the wrist's joint transform
  Real jaw_angle = 0;
  bool closed = true;
};

// eq. 15.
inline Pose world_pose(const InstrumentParams& params, const InstrumentState& state) {
  return state.controller * state.local * params.initial;
}

// eq. 16 with the rate of `command`, clamped to [0, theta_max]; updates `closed`.
void integrate_jaws(const JawParams& jaws, JawCommand command, Real dt, InstrumentState& state);

// The jaws' poses in the world: the tool pose turned by +theta (upper, opening towards +n) and
// -theta (lower, towards -n) about the hinge axis.
Pose upper_jaw_pose(const InstrumentParams& params, const InstrumentState& state);
Pose lower_jaw_pose(const InstrumentParams& params, const InstrumentState& state);

// Tip of a jaw (hinge + length along the jaw's f axis) in the world.
Vec3 jaw_tip(const InstrumentParams& params, const Pose& jaw);

}  // namespace imasim::surgery
