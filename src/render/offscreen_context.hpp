#pragma once
// An OpenGL 3.3 core context with no window and no display: EGL on Mesa's surfaceless platform
// (llvmpipe, the software rasteriser, where there is no GPU), drawing into a framebuffer object
// of a fixed size.
#include <cstdint>
#include <memory>
#include <vector>

namespace imasim::render {

class OffscreenContext {
 public:
  // Throws std::runtime_error saying what EGL or OpenGL refused.
  OffscreenContext(int width, int height);
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  int width() const { return width_; }
  int height() const { return height_; }
  // Makes this context current on the calling thread and binds its framebuffer as the draw
  // target (the renderer draws into whatever is bound). Several contexts may live in a process.
  void bind();
  // The drawn image, RGB, rows from the top.
  std::vector<std::uint8_t> read_rgb();
  // Window depth per pixel in [0, 1], rows from the top.
  std::vector<float> read_depth();
  // "OpenGL 4.5 (Core Profile) Mesa ... llvmpipe ...".
  const char* renderer_name() const;

 private:
  void make_current();
  struct Egl;
  std::unique_ptr<Egl> egl_;
  int width_, height_;
  unsigned framebuffer_ = 0, colour_ = 0, depth_ = 0;
};

}  // namespace imasim::render
