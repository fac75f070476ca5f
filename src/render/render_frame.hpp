#pragma once
// What the renderer draws: a read-only copy of the scene at one instant, in plain arrays of
// floats (the GPU's precision), built from the session by frame_of_session and handed from the
// physics thread to the drawing thread whole. Nothing here refers back to the simulation.
#include <array>
#include <cstdint>
#include <vector>

namespace imasim::render {

// What a surface is made of: its colour and its look (docs/rendering.md).
enum class Look : std::uint8_t {
  fascia,
  fat,
  ima,
  heart,
  chest_wall,
  bone,
  cartilage,
  instrument,
  electrode,
};
inline constexpr std::size_t kLookCount = 9;

const char* look_name(Look look);

// A triangle surface. `shade` per vertex in [0, 1]: 0 untouched tissue, 1 fully coagulated
// (drawn darkened and browned).
struct Surface {
  Look look = Look::fascia;
  std::vector<float> positions;        // x, y, z per vertex (unit: m)
  std::vector<float> normals;          // unit, per vertex
  std::vector<float> shade;            // per vertex
  std::vector<std::uint32_t> indices;  // three per triangle
  std::size_t vertex_count() const { return positions.size() / 3; }
  void clear() { positions.clear(), normals.clear(), shade.clear(), indices.clear(); }
};

// Spheres drawn as impostors (the fat's strand particles).
struct Spheres {
  Look look = Look::fat;
  std::vector<float> centres;  // x, y, z per sphere (unit: m)
  std::vector<float> radii;    // (unit: m)
  std::size_t count() const { return radii.size(); }
};

// Column-major 4x4 matrices, as OpenGL takes them.
using Matrix4 = std::array<float, 16>;

struct Camera {
  Matrix4 view{};        // world -> camera (camera looks along -z, +y up)
  Matrix4 projection{};  // camera -> clip, z in [-1, 1]
  std::array<float, 3> eye{};
};

struct RenderFrame {
  double time_s = 0;
  std::vector<Surface> surfaces;
  Spheres fat;
  Camera endoscope;  // the camera port's scope as the session has it
  // The cautery's glow: at the electrode while the pedal is pressed.
  bool glow = false;
  std::array<float, 3> glow_position{};
  float glow_strength = 0;  // 0..1, from the power
  // Bounds of the chest wall's patch (the orbit camera's default target and distance).
  std::array<float, 3> centre{};
  float radius = 0.1f;
};

}  // namespace imasim::render
