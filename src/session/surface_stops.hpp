#pragma once
// The guard that keeps the instruments' proxies out of the heart and the chest wall before a step
// (a god-object, SPEC S5): their probe points (the hinge and the tips) keep `tool_clearance` from
// both. A commanded motion goes as far as the surfaces let it and slides along the surface it
// meets; a surface that moved into an instrument (the beating heart) pushes it out along its
// normal. Within the step the rows of surface_stop_rows.hpp stop the proxy and make the force.
#include <array>

#include "session/surgical_session.hpp"

namespace imasim::session {

// Points of the instrument that must stay out of the heart and the wall: the hinge and the tips.
std::array<Vec3, 3> probe_points(const Station& station, Real electrode_length);

// With station.previous_controller where the instrument was (free) and station.state.controller
// the commanded pose (already through the port), leaves the instrument (state.controller, pose,
// arm_state.tool) where the surfaces let it be, and sets blocked_by_heart, blocked_by_wall and
// stop (where it rests and the surface's normal and velocity there).
void stop_at_surfaces(SurgicalSession& session, Station& station);

}  // namespace imasim::session
