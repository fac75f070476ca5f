#include "render/renderer.hpp"

#include <epoxy/gl.h>

#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "render/gl_program.hpp"
#include "render/look_style.hpp"
#include "render/shader_variant.hpp"
#include "render/shaders.hpp"
#include "render/sphere_order.hpp"
#include "render/sphere_shaders.hpp"

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

// The fat's spheres: centres and radii, per vertex for point sprites, per instance for the
// rectangles (with the rectangle's four corners per vertex).
struct SphereBuffers {
  GLuint vao = 0, corner = 0, centre = 0, radius = 0;

  explicit SphereBuffers(bool rectangles) {
    glGenVertexArrays(1, &vao);
    glBindVertexArray(vao);
    const GLuint first = rectangles ? 1 : 0;
    if (rectangles) {
      const float corners[] = {-1, -1, 1, -1, -1, 1, 1, 1};
      glGenBuffers(1, &corner);
      glBindBuffer(GL_ARRAY_BUFFER, corner);
      glBufferData(GL_ARRAY_BUFFER, sizeof corners, corners, GL_STATIC_DRAW);
      glEnableVertexAttribArray(0);
      glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 0, nullptr);
    }
    glGenBuffers(1, &centre);
    glBindBuffer(GL_ARRAY_BUFFER, centre);
    glEnableVertexAttribArray(first);
    glVertexAttribPointer(first, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
    glGenBuffers(1, &radius);
    glBindBuffer(GL_ARRAY_BUFFER, radius);
    glEnableVertexAttribArray(first + 1);
    glVertexAttribPointer(first + 1, 1, GL_FLOAT, GL_FALSE, 0, nullptr);
    if (rectangles) {
      glVertexAttribDivisor(first, 1);
      glVertexAttribDivisor(first + 1, 1);
    }
    glBindVertexArray(0);
  }
  ~SphereBuffers() {
    const GLuint buffers[] = {corner, centre, radius};
    glDeleteBuffers(3, buffers);  // 0 is ignored
    glDeleteVertexArrays(1, &vao);
  }
  SphereBuffers(const SphereBuffers&) = delete;
  SphereBuffers& operator=(const SphereBuffers&) = delete;

  void fill(const std::vector<float>& centres, const std::vector<float>& radii) const {
    glBindVertexArray(vao);
    glBindBuffer(GL_ARRAY_BUFFER, centre);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(centres.size() * sizeof(float)), centres.data(),
                 GL_STREAM_DRAW);
    glBindBuffer(GL_ARRAY_BUFFER, radius);
    glBufferData(GL_ARRAY_BUFFER, GLsizeiptr(radii.size() * sizeof(float)), radii.data(),
                 GL_STREAM_DRAW);
  }
};

std::string surface_fragment(ShaderVariant v) {
  return variant_fragment_source(v,
                                 std::string(shaders::kLighting) + shaders::kSurfaceFragmentMain);
}

std::string sphere_fragment(ShaderVariant v, const char* main) {
  return variant_fragment_source(v,
                                 std::string(shaders::kLighting) + shaders::kSphereRayCast + main);
}

// The three programs of one variant of the lighting (shader_variant.hpp).
struct Programs {
  GlProgram surface, sphere_point, sphere_quad;

  explicit Programs(ShaderVariant v)
      : surface(shaders::kSurfaceVertex, surface_fragment(v)),
        sphere_point(shaders::kSpherePointVertex,
                     sphere_fragment(v, shaders::kSpherePointFragmentMain)),
        sphere_quad(shaders::kSphereQuadVertex,
                    sphere_fragment(v, shaders::kSphereQuadFragmentMain)) {}
};

ShaderVariant variant_of(DrawMode mode, const RenderFrame& frame) {
  if (mode == DrawMode::look_colours) return ShaderVariant::key_colours;
  return frame.glow && frame.glow_strength > 0 ? ShaderVariant::lit_with_glow : ShaderVariant::lit;
}

}  // namespace

struct Renderer::Gl {
  // All variants are compiled up front, so that a shader error shows when the renderer is made.
  std::array<Programs, kShaderVariantCount> programs{Programs(ShaderVariant::lit),
                                                     Programs(ShaderVariant::lit_with_glow),
                                                     Programs(ShaderVariant::key_colours)};
  std::vector<SurfaceBuffers> surfaces;
  std::vector<std::pair<float, std::size_t>> order;  // surfaces by distance, nearest first
  SphereBuffers points{false}, rectangles{true};
  SphereOrder sphere_order;  // the fat nearest first (sphere_order.hpp)
  float max_point_size = 1;  // the largest sprite the rasteriser draws (unit: pixel)

  Gl() {
    GLfloat range[2] = {1, 1};
    glGetFloatv(GL_POINT_SIZE_RANGE, range);
    max_point_size = range[1];
  }

  ~Gl() {
    for (SurfaceBuffers& b : surfaces) {
      const GLuint buffers[] = {b.position, b.normal, b.shade, b.index};
      glDeleteBuffers(4, buffers);
      glDeleteVertexArrays(1, &b.vao);
    }
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
    if (variant_of(mode, frame) != ShaderVariant::lit_with_glow) return;
    const float* v = camera.view.data();
    const std::array<float, 3>& g = frame.glow_position;
    const float gx = v[0] * g[0] + v[4] * g[1] + v[8] * g[2] + v[12];
    const float gy = v[1] * g[0] + v[5] * g[1] + v[9] * g[2] + v[13];
    const float gz = v[2] * g[0] + v[6] * g[1] + v[10] * g[2] + v[14];
    glUniform3f(p.uniform("u_glow_position"), gx, gy, gz);
    glUniform1f(p.uniform("u_glow"), frame.glow_strength);
  }
};

Renderer::Renderer() : gl_(std::make_unique<Gl>()) {}
Renderer::~Renderer() = default;

std::array<float, 3> background_colour(DrawMode mode) {
  return mode == DrawMode::look_colours ? std::array<float, 3>{0, 0, 0} : kBackground;
}

void Renderer::draw(const RenderFrame& frame, const Camera& camera, const Viewport& viewport,
                    DrawMode mode, std::array<bool, 3> colour_mask, Clear clear) {
  glViewport(viewport.x, viewport.y, viewport.width, viewport.height);
  glEnable(GL_SCISSOR_TEST);
  glScissor(viewport.x, viewport.y, viewport.width, viewport.height);
  glColorMask(colour_mask[0], colour_mask[1], colour_mask[2], GL_TRUE);
  if (clear == Clear::viewport) {
    const std::array<float, 3> b = background_colour(mode);
    glClearColor(b[0], b[1], b[2], 1);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glCullFace(GL_BACK);
  glFrontFace(GL_CCW);

  Programs& programs = gl_->programs[std::size_t(variant_of(mode, frame))];
  gl_->set_common(programs.surface, frame, camera, mode);
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
    gl_->set_look(programs.surface, s.look, mode);
    // Closed surfaces hide their own back faces: not rasterising them saves their shading.
    if (is_closed(s.look))
      glEnable(GL_CULL_FACE);
    else
      glDisable(GL_CULL_FACE);
    glDrawElements(GL_TRIANGLES, GLsizei(s.indices.size()), GL_UNSIGNED_INT, nullptr);
  }

  if (frame.fat.count() > 0) {
    SphereOrder& order = gl_->sphere_order;
    order.sort(frame.fat, camera.eye);
    order.split_sprites(camera, float(viewport.width), float(viewport.height),
                        0.9f * gl_->max_point_size);
    // The nearest first: the rectangles of spheres too big for a sprite (seldom any), then the
    // sprites.
    if (!order.near_radii().empty()) {
      gl_->set_common(programs.sphere_quad, frame, camera, mode);
      gl_->set_look(programs.sphere_quad, frame.fat.look, mode);
      gl_->rectangles.fill(order.near_centres(), order.near_radii());
      glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, GLsizei(order.near_radii().size()));
    }
    if (!order.radii().empty()) {
      gl_->set_common(programs.sphere_point, frame, camera, mode);
      gl_->set_look(programs.sphere_point, frame.fat.look, mode);
      glUniform4f(programs.sphere_point.uniform("u_viewport"), float(viewport.x), float(viewport.y),
                  float(viewport.width), float(viewport.height));
      gl_->points.fill(order.centres(), order.radii());
      glEnable(GL_PROGRAM_POINT_SIZE);
      glDrawArrays(GL_POINTS, 0, GLsizei(order.radii().size()));
      glDisable(GL_PROGRAM_POINT_SIZE);
    }
  }
  glDisable(GL_CULL_FACE);
  glBindVertexArray(0);
  glUseProgram(0);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glDisable(GL_SCISSOR_TEST);
}

}  // namespace imasim::render
