#pragma once
// The two views of the scene: the endoscope's (from the frame) and a free orbit camera about a
// target, with their stereo pairs (docs/rendering.md).
#include "render/render_frame.hpp"

namespace imasim::render {

struct OrbitCamera {
  std::array<float, 3> target{};
  float distance = 0.25f;                       // (unit: m)
  float yaw = 0.6f, pitch = -0.5f;              // (unit: rad)
  float vertical_fov = 0.9f;                    // (unit: rad)
  float near_plane = 0.002f, far_plane = 2.0f;  // (unit: m)
};

// Looks at the frame's tissue from outside, the default orbit.
OrbitCamera default_orbit(const RenderFrame& frame);

Camera orbit_camera(const OrbitCamera& orbit, float aspect);

// The endoscope's camera with its projection widened or narrowed to `aspect` (width / height),
// keeping its vertical field of view.
Camera endoscope_camera(const RenderFrame& frame, float aspect);

// One eye of a stereo pair: the camera moved by half the eye separation along its right axis,
// `eye` -1 (left) or +1 (right); `separation` (unit: m), `convergence` distance (unit: m)
// where the two images coincide (an asymmetric frustum shift).
Camera stereo_eye(const Camera& centre, int eye, float separation, float convergence);

Matrix4 multiply(const Matrix4& a, const Matrix4& b);
// The pixel (x right, y down, from the top-left) and the window depth in [0, 1] of a world point,
// or false when it is behind the camera.
bool project(const Camera& camera, const std::array<float, 3>& world, int width, int height,
             float& x, float& y, float& depth);

}  // namespace imasim::render
