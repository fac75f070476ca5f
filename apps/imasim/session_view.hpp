#pragma once
// A picture of the session as the study's report shows it: the scene drawn offscreen
// (EGL, no display) from the default orbit, which looks at the fascia, the fat and the heart from
// the cavity's side, written as a PNG file.
#include <string>

#include "session/surgical_session.hpp"

namespace imasim::cli {

inline constexpr int kSessionViewWidth = 640, kSessionViewHeight = 360;

// Throws std::runtime_error (no OpenGL through EGL, or the file cannot be written).
void draw_session_view(const session::SurgicalSession& session, const std::string& png_path);

}  // namespace imasim::cli
