#include "render/camera.hpp"

#include <cmath>

namespace imasim::render {

namespace {

using V3 = std::array<float, 3>;

V3 sub(const V3& a, const V3& b) {
  return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}
V3 cross(const V3& a, const V3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
float dot(const V3& a, const V3& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
V3 normalised(const V3& a) {
  const float n = std::sqrt(dot(a, a));
  return n > 0 ? V3{a[0] / n, a[1] / n, a[2] / n} : a;
}

Matrix4 look_at(const V3& eye, const V3& target, const V3& up_hint) {
  const V3 f = normalised(sub(target, eye));
  V3 r = normalised(cross(f, up_hint));
  if (dot(r, r) < 0.5f) r = normalised(cross(f, V3{1, 0, 0}));
  const V3 u = cross(r, f);
  Matrix4 m{};
  m[0] = r[0], m[4] = r[1], m[8] = r[2], m[12] = -dot(r, eye);
  m[1] = u[0], m[5] = u[1], m[9] = u[2], m[13] = -dot(u, eye);
  m[2] = -f[0], m[6] = -f[1], m[10] = -f[2], m[14] = dot(f, eye);
  m[15] = 1;
  return m;
}

Matrix4 perspective(float vertical_fov, float aspect, float near_plane, float far_plane) {
  const float f = 1.0f / std::tan(vertical_fov / 2);
  Matrix4 m{};
  m[0] = f / aspect;
  m[5] = f;
  m[10] = (far_plane + near_plane) / (near_plane - far_plane);
  m[11] = -1;
  m[14] = 2 * far_plane * near_plane / (near_plane - far_plane);
  return m;
}

}  // namespace

Matrix4 multiply(const Matrix4& a, const Matrix4& b) {
  Matrix4 m{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) {
      float s = 0;
      for (int k = 0; k < 4; ++k)
        s += a[k * 4 + r] * b[c * 4 + k];
      m[c * 4 + r] = s;
    }
  return m;
}

OrbitCamera default_orbit(const RenderFrame& frame) {
  OrbitCamera o;
  o.target = frame.centre;
  // From the cavity's side (-y, the heart's side of the wall) and from the head's end of the
  // vessel (-z), where the heart is not between the eye and the fascia, a little lateral (+x).
  const float dx = 0.3f, dy = -0.8f, dz = -1.0f;
  o.yaw = std::atan2(dy, dx);
  o.pitch = std::asin(-dz / std::sqrt(dx * dx + dy * dy + dz * dz));
  o.distance = std::max(0.05f, 1.5f * frame.radius);
  o.far_plane = 20 * o.distance;
  return o;
}

Camera orbit_camera(const OrbitCamera& orbit, float aspect) {
  // z is the body's up in the scene's frame; yaw about it, pitch above the horizontal.
  const V3 offset{std::cos(orbit.pitch) * std::cos(orbit.yaw),
                  std::cos(orbit.pitch) * std::sin(orbit.yaw), -std::sin(orbit.pitch)};
  const V3 eye{orbit.target[0] + orbit.distance * offset[0],
               orbit.target[1] + orbit.distance * offset[1],
               orbit.target[2] + orbit.distance * offset[2]};
  Camera c;
  c.view = look_at(eye, orbit.target, V3{0, 0, 1});
  c.projection = perspective(orbit.vertical_fov, aspect, orbit.near_plane, orbit.far_plane);
  c.eye = eye;
  return c;
}

Camera endoscope_camera(const RenderFrame& frame, float aspect) {
  Camera c = frame.endoscope;
  // x scale = y scale / aspect (the session's projection keeps its own aspect).
  c.projection[0] = c.projection[5] / aspect;
  return c;
}

Camera stereo_eye(const Camera& centre, int eye, float separation, float convergence) {
  Camera c = centre;
  const float half = 0.5f * separation * float(eye);
  // Move the camera along its own x axis: the view's translation changes by -half in x.
  c.view[12] -= half;
  // Shift the frustum so that the planes at `convergence` coincide: x_clip += P00 half / d.
  c.projection[8] -= c.projection[0] * half / convergence;
  // The eye in the world: the camera's x axis is the view's first row.
  c.eye = {centre.eye[0] + half * centre.view[0], centre.eye[1] + half * centre.view[4],
           centre.eye[2] + half * centre.view[8]};
  return c;
}

bool project(const Camera& camera, const std::array<float, 3>& world, int width, int height,
             float& x, float& y, float& depth) {
  const Matrix4 m = multiply(camera.projection, camera.view);
  float clip[4];
  for (int r = 0; r < 4; ++r)
    clip[r] = m[r] * world[0] + m[4 + r] * world[1] + m[8 + r] * world[2] + m[12 + r];
  if (!(clip[3] > 0)) return false;
  const float nx = clip[0] / clip[3], ny = clip[1] / clip[3], nz = clip[2] / clip[3];
  x = (nx * 0.5f + 0.5f) * float(width);
  y = (1 - (ny * 0.5f + 0.5f)) * float(height);
  depth = nz * 0.5f + 0.5f;
  return true;
}

}  // namespace imasim::render
