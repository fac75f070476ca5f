#pragma once
// The session as the renderer sees it: tissue surfaces (the fascia, the fine IMA mesh, the
// chest wall), the beating heart, the chest skeleton, the fat's strand particles, both
// instruments with their jaws, the electrode and its glow, the endoscope's camera.
#include "render/render_frame.hpp"
#include "session/surgical_session.hpp"

namespace imasim::render {

// Fills `out`, reusing its buffers (no allocation once they have grown to the scene's size).
void frame_of_session(const session::SurgicalSession& session, RenderFrame& out);

}  // namespace imasim::render
