#pragma once
// A robotic arm holding an instrument through its port (SPEC S4 reading): the port is a remote
// centre of motion, the shaft always passes through it; the hand's motion on the console is
// scaled down (3:1 by default, as on robotic consoles), its rotation is not; a clutch lets the
// hand re-centre while the instrument holds still. The arm turns the hand's pose into the
// instrument's T_controller (eq. 15).
//
// The hinge (tool frame origin) is where the hand puts it, scaled, at least `min_insertion`
// beyond the port; the shaft runs from the port through the hinge. A wrist at the shaft's end
// lets the jaws take the hand's orientation within `wrist_limit` of the shaft axis.
#include "math/pose.hpp"

namespace imasim::surgery {

struct ArmParams {
  Vec3 port = Vec3::Zero();         // the pivot (unit: m)
  Real motion_scale = Real(1) / 3;  // tool displacement per hand displacement
  Real min_insertion = Real(0.02);  // hinge beyond the port (unit: m)
  Real max_insertion = Real(0.30);  // (unit: m)
  Real wrist_limit = Real(1.4);     // largest angle between jaws' f axis and the shaft (rad)
};

struct ArmState {
  bool clutched = false;
  Pose hand_anchor;  // hand pose when the current (unclutched) motion began
  Pose tool_anchor;  // commanded tool pose then
  Pose commanded;    // tool pose the hand asks for (before the port's constraint)
  Pose tool;         // the instrument's pose: the hinge, its orientation (T_controller)
};

// Places the tool at `start` (projected onto the port's constraint) with the hand at `hand`.
ArmState make_arm_state(const ArmParams& params, const Pose& start, const Pose& hand);

// One update from the hand's pose and the clutch pedal. While clutched the tool holds; on
// release the motion continues from the hand's new pose.
void update_arm(const ArmParams& params, const Pose& hand, bool clutch, ArmState& state);

// The pose the port allows nearest a commanded pose: the hinge at the commanded point, pulled
// into [min, max] insertion along the line from the port; the orientation turned by the least
// rotation that brings its f axis within the wrist limit of the shaft.
Pose constrain_to_port(const ArmParams& params, const Pose& commanded);

// A rotation whose f axis (third column) is the unit `f`: l = R (1, 0, 0) across (z x f, or x x f
// when f is along z), n = f x l.
Mat3 frame_along(const Vec3& f);

// Unit shaft direction, from the port towards the hinge.
Vec3 shaft_direction(const ArmParams& params, const ArmState& state);

}  // namespace imasim::surgery
