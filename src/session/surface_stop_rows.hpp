#pragma once
// The heart and the chest wall stop each instrument's proxy inside the solve: rows
// between its body and their tangent planes (physics/body_stop.hpp) at its probe points (the
// hinge and the tips, surface_stops.hpp), so their push on the tool is part of the step and of
// the tool's force, like the tissue's. The heart also stops the jaws at each point they hold
// tissue by, with the heart's own margin (held tissue has no heart rows: tissue::drop_held_rows).
// The god-object stop before the step (surface_stops.hpp)
// remains as the guard against a motion that would pass through them between two steps.
#include <cstdint>
#include <span>
#include <vector>

#include "physics/body_stop.hpp"
#include "session/surgical_session.hpp"

namespace imasim::session {

// After the heart has been advanced to the step's end (its `previous` at the step's start):
// appends the rows of station `st`, whose proxy is body `body`, for every probe point within
// reach of the heart or the wall over the step, and for every point its jaws hold (the state's
// body attachments on `body`) within reach of the heart. Tag: the surgery::Tissue stopped.
void gather_surface_stop_rows(SurgicalSession& s, const Station& st, std::uint32_t body,
                              std::vector<physics::BodyStopRow>& out);

// After the step, with the station's rows (`rows`) and the offset the solve carried its proxy
// by: if any pushed the proxy, the one that pushed most becomes the station's stop (its point
// where the step left it, the surface's normal and velocity, and the force of all that surface's
// rows on the tool) and sets blocked_by_heart or blocked_by_wall; returns that surface (none if
// no row pushed). dt: the step (unit: s).
surgery::Tissue note_surface_stop_rows(Station& st, std::span<const physics::BodyStopRow> rows,
                                       const Vec3& carried, Real dt);

}  // namespace imasim::session
