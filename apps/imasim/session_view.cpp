#include "session_view.hpp"

#include "render/camera.hpp"
#include "render/frame_of_session.hpp"
#include "render/image_file.hpp"
#include "render/offscreen_context.hpp"
#include "render/renderer.hpp"

namespace imasim::cli {

void draw_session_view(const session::SurgicalSession& session, const std::string& png_path) {
  render::OffscreenContext context(kSessionViewWidth, kSessionViewHeight);
  render::Renderer renderer;
  render::RenderFrame frame;
  render::frame_of_session(session, frame);
  context.bind();
  const render::Camera camera = render::orbit_camera(
      render::default_orbit(frame), float(kSessionViewWidth) / float(kSessionViewHeight));
  renderer.draw(frame, camera, {0, 0, kSessionViewWidth, kSessionViewHeight});
  render::write_png(png_path, {kSessionViewWidth, kSessionViewHeight, context.read_rgb()});
}

}  // namespace imasim::cli
