#include "render/renderer.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <string>
#include <vector>

#include "render/gl_program.hpp"
#include "render/look_style.hpp"
#include "render/shaders.hpp"
#include "render/sphere_order.hpp"

namespace imasim::render {

namespace {

// One surface's buffers, refilled every frame (the tissue moves every frame).
struct SurfaceBuffers {
  GLuint vao = 0, position = 0, normal = 0, shade = 0, index = 0;
};

// Surfaces that enclose a volume, wound counter-clockwise seen from outside; the membranes
// (fascia, wall) are seen from both sides.
bool is_closed(Look look) {
  return look == Look::heart || look == Look::bone || look == Look::cartilage ||
         look == Look::instrument || look == Look::electrode;
}

// The distance from the eye to the centre of a surface's bounding box.
float distance_from_eye(const Surface& s, const Camera& camera) {
  std::array<float, 3> lo{1e30f, 1e30f, 1e30f}, hi{-1e30f, -1e30f, -1e30f};
  for (std::size_t i = 0; i + 2 < s.positions.size(); i += 3)
    for (std::size_t k = 0; k < 3; ++k) {
      lo[k] = std::min(lo[k], s.positions[i + k]);
      hi[k] = std::max(hi[k], s.positions[i + k]);
    }
  float d2 = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    const float c = 0.5f * (lo[k] + hi[k]) - camera.eye[k];
    d2 += c * c;
  }
  return d2;
}

const std::array<float, 3> kBackground = {0.06f, 0.025f, 0.025f};  // the cavity's dark

}  // namespace

struct Renderer::Gl {
  GlProgram surface{
      shaders::kSurfaceVertex,
      std::string("#version 330 core\n") + shaders::kLighting + shaders::kSurfaceFragmentMain};
  GlProgram sphere{shaders::kSphereVertex, std::string("#version 330 core\n") + shaders::kLighting +
                                               shaders::kSphereFragmentMain};
  std::vector<SurfaceBuffers> surfaces;
  std::vector<std::pair<float, std::size_t>> order;  // surfaces by distance, nearest first
  GLuint sphere_vao = 0, sphere_corner = 0, sphere_centre = 0, sphere_radius = 0;
  SphereOrder sphere_order;  // the fat nearest first (sphere_order.hpp)

  Gl() {
    glGenVertexArrays(1, &sphere_vao);
    glBindVertexArray(sphere_vao);
    const float corners[] = {-1, -1, 1, -1, -1, 1, 1, 1};
    glGenBuffers(1, &sphere_corner);
    glBindBuffer(GL_ARRAY_BUFFER, sphere_corner);
    glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    glGenBuffers(1, &sphere_centre);
    glBindBuffer(GL_ARRAY_BUFFER, sphere_centre);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glVertexAttribDivisor(1, 1);
    glGenBuffers(1, &sphere_radius);
    glBindBuffer(GL_ARRAY_BUFFER, sphere_radius);
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 1, GL_FLOAT, GL_FALSE, 0, nullptr);
    glVertexAttribDivisor(2, 1);
    glBindVertexArray(0);
  }

  ~Gl() {
    for (SurfaceBuffers& b : surfaces) {
      const GLuint buffers[] = {b.position, b.normal, b.shade, b.index};
      glDeleteBuffers(4, buffers);
      glDeleteVertexArrays(1, &b.vao);
    }
    const GLuint buffers[] = {sphere_corner, sphere_centre, sphere_radius};
    glDeleteBuffers(3, buffers);
    glDeleteVertexArrays(1, &sphere_vao);
  }

  SurfaceBuffers& buffers(std::size_t i) {
    while (surfaces.size() <= i) {
      SurfaceBuffers b;
      glGenVertexArrays(1, &b.vao);
      glBindVertexArray(b.vao);
      GLuint ids[4];
      glGenBuffers(4, ids);
      b.position = ids[0], b.normal = ids[1], b.shade = ids[2], b.index = ids[3];
      const std::pair<GLuint, GLint> attributes[] = {{b.position, 3}, {b.normal, 3}, {b.shade, 1}};
      for (GLuint a = 0; a < 3; ++a) {
        glBindBuffer(GL_ARRAY_BUFFER, attributes[a].first);
        glEnableVertexAttribArray(a);
        glVertexAttribPointer(a, attributes[a].second, GL_FLOAT, GL_FALSE, 0, nullptr);
      }
      glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, b.index);
      glBindVertexArray(0);
      surfaces.push_back(b);
    }
    return surfaces[i];
  }

  void set_look(const GlProgram& p, Look look, DrawMode mode) {
    const LookStyle s = look_style(look);
    if (mode == DrawMode::look_colours) {
      const std::array<std::uint8_t, 3> k = key_colour(look);
      glUniform3f(p.uniform("u_colour"), float(k[0]) / 255, float(k[1]) / 255, float(k[2]) / 255);
    } else {
      glUniform3f(p.uniform("u_colour"), s.colour[0], s.colour[1], s.colour[2]);
    }
    glUniform1f(p.uniform("u_specular"), s.specular);
    glUniform1f(p.uniform("u_shininess"), s.shininess);
  }

  void set_common(const GlProgram& p, const RenderFrame& frame, const Camera& camera,
                  DrawMode mode) {
    glUseProgram(p.id());
    glUniformMatrix4fv(p.uniform("u_view"), 1, GL_FALSE, camera.view.data());
    glUniformMatrix4fv(p.uniform("u_projection"), 1, GL_FALSE, camera.projection.data());
    glUniform1i(p.uniform("u_key"), mode == DrawMode::look_colours ? 1 : 0);
    const float* v = camera.view.data();
    const std::array<float, 3>& g = frame.glow_position;
    const float gx = v[0] * g[0] + v[4] * g[1] + v[8] * g[2] + v[12];
    const float gy = v[1] * g[0] + v[5] * g[1] + v[9] * g[2] + v[13];
    const float gz = v[2] * g[0] + v[6] * g[1] + v[10] * g[2] + v[14];
    glUniform3f(p.uniform("u_glow_position"), gx, gy, gz);
    glUniform1f(p.uniform("u_glow"), mode == DrawMode::lit && frame.glow ? frame.glow_strength : 0);
  }
};

Renderer::Renderer() : gl_(std::make_unique<Gl>()) {}
Renderer::~Renderer() = default;

void Renderer::draw(const RenderFrame& frame, const Camera& camera, const Viewport& viewport,
                    DrawMode mode, std::array<bool, 3> colour_mask, bool clear) {
  glViewport(viewport.x, viewport.y, viewport.width, viewport.height);
  glEnable(GL_SCISSOR_TEST);
  glScissor(viewport.x, viewport.y, viewport.width, viewport.height);
  glColorMask(colour_mask[0], colour_mask[1], colour_mask[2], GL_TRUE);
  if (clear) {
    if (mode == DrawMode::look_colours)
      glClearColor(0, 0, 0, 1);
    else
      glClearColor(kBackground[0], kBackground[1], kBackground[2], 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  } else {
    glClear(GL_DEPTH_BUFFER_BIT);
  }
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glCullFace(GL_BACK);
  glFrontFace(GL_CCW);

  gl_->set_common(gl_->surface, frame, camera, mode);
  // Nearest surfaces first: what they hide then fails the depth test before it is shaded.
  gl_->order.clear();
  for (std::size_t i = 0; i < frame.surfaces.size(); ++i)
    gl_->order.push_back({distance_from_eye(frame.surfaces[i], camera), i});
  std::sort(gl_->order.begin(), gl_->order.end());
  for (const auto& [distance, i] : gl_->order) {
    const Surface& s = frame.surfaces[i];
    if (s.indices.empty()) continue;
    SurfaceBuffers& b = gl_->buffers(i);
    glBindVertexArray(b.vao);
    glBindBuffer(GL_ARRAY_BUFFER, b.position);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(s.positions.size() * sizeof(float)),
                 s.positions.data(), GL_STREAM_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, b.normal);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(s.normals.size() * sizeof(float)), s.normals.data(),
                 GL_STREAM_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, b.shade);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(s.shade.size() * sizeof(float)), s.shade.data(),
                 GL_STREAM_DRAW);
    glBufferData(GL_ELEMENT_ARRAY_BUFFER, GLsizeiptr(s.indices.size() * sizeof(std::uint32_t)),
                 s.indices.data(), GL_STREAM_DRAW);
    gl_->set_look(gl_->surface, s.look, mode);
    // Closed surfaces hide their own back faces: not rasterising them saves their shading.
    if (is_closed(s.look))
      glEnable(GL_CULL_FACE);
    else
      glDisable(GL_CULL_FACE);
    glDrawElements(GL_TRIANGLES, GLsizei(s.indices.size()), GL_UNSIGNED_INT, nullptr);
  }

  if (frame.fat.count() > 0) {
    gl_->set_common(gl_->sphere, frame, camera, mode);
    gl_->set_look(gl_->sphere, frame.fat.look, mode);
    gl_->sphere_order.sort(frame.fat, camera.eye);
    glBindVertexArray(gl_->sphere_vao);
    glBindBuffer(GL_ARRAY_BUFFER, gl_->sphere_centre);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(gl_->sphere_order.centres().size() * sizeof(float)),
                 gl_->sphere_order.centres().data(), GL_STREAM_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, gl_->sphere_radius);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(gl_->sphere_order.radii().size() * sizeof(float)),
                 gl_->sphere_order.radii().data(), GL_STREAM_DRAW);
    glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(frame.fat.count()));
  }
  glDisable(GL_CULL_FACE);
  glBindVertexArray(0);
  glUseProgram(0);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_SCISSOR_TEST);
}

}  // namespace imasim::render
