#pragma once
// Where an instrument works, for the recorder and the scores (SPEC S6's "tool positions"): the
// forceps' tip is the midpoint of its two jaw tips, the cautery hook's the end of its electrode.
#include "session/surgical_session.hpp"

namespace imasim::session {

Vec3 tool_tip(const SurgicalSession& session, int station);

}  // namespace imasim::session
