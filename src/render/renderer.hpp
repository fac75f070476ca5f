#pragma once
// Draws a RenderFrame with OpenGL 3.3 core into the bound framebuffer: lit tissue with a wet
// look (Blinn-Phong with a strong, narrow highlight and a Fresnel rim), coagulated tissue
// darkened, the fat as sphere impostors, the cautery's glow as a warm point light. Needs a
// current context (OffscreenContext or the window's); owns its GL objects.
#include <memory>

#include "render/render_frame.hpp"

namespace imasim::render {

enum class DrawMode {
  lit,          // the picture a surgeon sees
  look_colours  // each look in its flat key colour, unlit (tests find tissues by colour)
};

// The flat colour of a look in DrawMode::look_colours, RGB 0..255.
std::array<std::uint8_t, 3> key_colour(Look look);

// What shows where nothing is drawn: the cavity's dark (black with key colours), RGB 0..1.
std::array<float, 3> background_colour(DrawMode mode);

// How a draw starts: by clearing its viewport, or on a target its caller has cleared (colour
// to background_colour, depth to the far plane). Mesa clears a viewport smaller than the
// target by drawing a rectangle over it, while a clear of the whole target costs llvmpipe
// almost nothing: a window with panels beside the view clears once for both.
enum class Clear { viewport, done_by_caller };

struct Viewport {
  int x = 0, y = 0, width = 1, height = 1;
};

class Renderer {
 public:
  Renderer();  // compiles the shaders; throws std::runtime_error with the compiler's log
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  // Clears the viewport (unless the caller did) and draws. `colour_mask` for anaglyph stereo
  // (r, g, b written).
  void draw(const RenderFrame& frame, const Camera& camera, const Viewport& viewport,
            DrawMode mode = DrawMode::lit, std::array<bool, 3> colour_mask = {true, true, true},
            Clear clear = Clear::viewport);

 private:
  struct Gl;
  std::unique_ptr<Gl> gl_;
};

}  // namespace imasim::render
