#pragma once
// The scripted operator's plan for the paper's standard task (SPEC S6): harvest a 10 cm segment
// of the left IMA. Made once, before the first step, from what a surgeon sees of the scene
// (the description: the vessel's course at rest, the fascia, the chest wall, the heart and how
// far it moves over a beat), never from the tissue's current state. The plan is a timeline of
// tool poses (the hinge in the scene frame, as a tracker on the instrument gives it), jaw
// targets and the pedal; the operator (scripted_operator.hpp) plays it through the device
// interface with tremor.
//
// The phases, each proximal (cranial) to distal (caudal) along the segment:
//   1. open: the hook in cut mode draws an incision through the fascia along the vessel on each
//      side of it, the side away from the heart first;
//   2. divide: per 2 cm section, the forceps grasp the outer lip of the incision away from the
//      heart and retract it, and the hook sweeps in cut mode through the fat that holds the
//      vessel to the chest wall, on the side away from the heart, then on the heart's side;
//      with those strands divided the pedicle is free;
//   3. withdraw: the tools leave the freed pedicle.
// Every tool pose keeps `keep_out` from the heart's surface where the wall leaves room: the
// operator works higher (towards the wall) the more the heart moves.
#include <string>
#include <vector>

#include "autopilot/operator_params.hpp"
#include "haptics/tissue_kind.hpp"
#include "math/pose.hpp"
#include "session/surgical_session.hpp"

namespace imasim::autopilot {

struct ToolKey {
  double time = 0;  // (unit: s)
  Pose tool;        // the hinge in the scene frame (unit: m)
  Real jaw = 0;     // target: 0 open .. 1 closed
};

struct PedalKey {
  double time = 0;  // (unit: s)
  haptics::CauteryMode mode = haptics::CauteryMode::off;
  Real power_w = 40;  // the generator's setting from this time on (unit: W)
};

struct PhaseMark {
  double time = 0;  // (unit: s)
  std::string name;
};

struct HarvestPlan {
  std::vector<ToolKey> forceps, hook;  // times non-decreasing
  std::vector<PedalKey> pedal;
  std::vector<PhaseMark> phases;
  std::vector<Vec3> segment;  // the harvested part of the IMA's centerline at rest (unit: m)
  Real heart_excursion = 0;   // largest heart motion under the segment over a beat (unit: m)
  Real keep_out = 0;          // distance kept from the heart's surface (unit: m)
  Real electrode_length = 0;  // the hook's, hinge to tip (unit: m)
  double end_time = 0;        // (unit: s)
};

// Throws std::invalid_argument when the scene has no segment of the asked length or the
// parameters are out of range.
HarvestPlan plan_harvest(const session::SurgicalSession& session, const OperatorParams& params);

}  // namespace imasim::autopilot
