#pragma once
// GLSL 3.30 core sources of the fat's sphere impostors (docs/rendering.md), after the shared
// lighting of shaders.hpp. Each sphere is ray-cast in the fragment shader for its outline and
// its normal; the depth written is the centre's (the fat's spheres are under 2 mm across):
// writing each fragment's true depth turns off the rasteriser's early depth test, which cost
// llvmpipe a quarter of the frame (docs/PERFORMANCE.md).
namespace imasim::render::shaders {

// Most spheres: one point sprite each, about the tight screen bounds of the outline
// (render/sphere_sprite.hpp has the formulas and the same computation on the CPU). A point is
// one vertex where a rectangle was four: llvmpipe shades vertices and sets up primitives on the
// drawing thread, one instance at a time, and the rectangles' were a fifth of the frame.
inline constexpr const char* kSpherePointVertex = R"(#version 330 core
layout(location = 0) in vec3 a_centre;
layout(location = 1) in float a_radius;
uniform mat4 u_view;
uniform mat4 u_projection;
uniform vec4 u_viewport;  // x, y, width, height (pixels)
flat out vec3 v_centre;
flat out float v_radius;
vec2 tangent_slopes(float x, float d, float r) {
  float t = sqrt(max(x * x + d * d - r * r, 0.0));
  return vec2((x * t - d * r) / (d * t + x * r), (x * t + d * r) / (d * t - x * r));
}
const vec4 kCulled = vec4(0.0, 0.0, 2.0, 1.0);  // beyond the far plane
void main() {
  vec3 c = (u_view * vec4(a_centre, 1.0)).xyz;
  float r = a_radius;
  float d = -c.z;
  v_centre = c;
  v_radius = r;
  gl_PointSize = 1.0;
  // Spheres reaching the eye's plane are drawn as rectangles (the renderer sends them there).
  if (d <= r * 1.0001) { gl_Position = kCulled; return; }
  vec2 sx = tangent_slopes(c.x, d, r), sy = tangent_slopes(c.y, d, r);
  vec2 lo = vec2(u_projection[0][0] * sx.x, u_projection[1][1] * sy.x) - u_projection[2].xy;
  vec2 hi = vec2(u_projection[0][0] * sx.y, u_projection[1][1] * sy.y) - u_projection[2].xy;
  if (any(lessThan(hi, vec2(-1.0))) || any(greaterThan(lo, vec2(1.0)))) {
    gl_Position = kCulled;
    return;
  }
  // A point whose centre is outside the view is not drawn at all: a sphere partly in view keeps
  // its sprite's centre just inside the edge, and the sprite grows to reach its far side.
  vec2 middle = clamp(0.5 * (lo + hi), vec2(-0.999), vec2(0.999));
  vec2 reach_px = max(middle - lo, hi - middle) * u_viewport.zw;
  // 1 % and a pixel beyond the exact outline, for the rasteriser's rounding.
  gl_PointSize = 1.01 * max(reach_px.x, reach_px.y) + 1.0;
  vec4 clip = u_projection * vec4(c, 1.0);
  gl_Position = vec4(middle * clip.w, clip.z, clip.w);
}
)";

// Both impostors' fragments: the sphere met along the unit ray d from the eye, shaded; a ray
// that misses it discards the fragment.
inline constexpr const char* kSphereRayCast = R"(
flat in vec3 v_centre;
flat in float v_radius;
out vec4 o_colour;
void shade_sphere_along(vec3 d) {
  float b = dot(d, v_centre);
  float disc = b * b - dot(v_centre, v_centre) + v_radius * v_radius;
  if (disc < 0.0) discard;
  float t = b - sqrt(disc);
  if (t <= 0.0) discard;
  vec3 hit = t * d;
  o_colour = vec4(shade_colour(hit, (hit - v_centre) / v_radius, 0.0), 1.0);
}
)";

inline constexpr const char* kSpherePointFragmentMain = R"(
uniform mat4 u_projection;
uniform vec4 u_viewport;
void main() {
  // The ray through the pixel's centre, from window back to camera coordinates.
  vec2 ndc = 2.0 * (gl_FragCoord.xy - u_viewport.xy) / u_viewport.zw - 1.0;
  vec2 slope = (ndc + u_projection[2].xy) / vec2(u_projection[0][0], u_projection[1][1]);
  shade_sphere_along(normalize(vec3(slope, -1.0)));
}
)";

// Spheres too big for a point sprite (near the eye, or reaching its plane): a rectangle per
// sphere in the camera-facing plane of its centre. The rectangle is the exact bound of the
// outline in that plane: seen from the eye the outline is the cone of half-angle a
// (sin a = r / d) about the centre's direction, which cuts the plane z = c.z in an ellipse.
// Along the radial direction u (the centre's, off the view axis by t) it spans
// |c.z| tan(t -+ a) from the axis; across it, |c.z| r / sqrt(c.z^2 - r^2): off the axis it is
// longer by about 1 / cos t (1.4 at the corners of a 0.9 rad view).
inline constexpr const char* kSphereQuadVertex = R"(#version 330 core
layout(location = 0) in vec2 a_corner;
layout(location = 1) in vec3 a_centre;
layout(location = 2) in float a_radius;
uniform mat4 u_view;
uniform mat4 u_projection;
out vec3 v_position;
flat out vec3 v_centre;
flat out float v_radius;
void main() {
  vec3 c = (u_view * vec4(a_centre, 1.0)).xyz;
  float r = a_radius;
  float depth = -c.z;  // in front of the eye when positive
  float rho = length(c.xy);
  vec2 u = rho > 1e-9 ? c.xy / rho : vec2(1.0, 0.0);
  vec2 v = vec2(-u.y, u.x);
  float tan_t = rho / max(depth, 1e-9);
  float tan_a = r * inversesqrt(max(dot(c, c) - r * r, 1e-18));
  float below = 1.0 - tan_t * tan_a;  // the cone's far side meets the plane while positive
  vec2 half_size;
  vec2 middle;
  if (depth > r && below > 0.0) {
    float far_side = depth * (tan_t + tan_a) / below;
    float near_side = depth * (tan_t - tan_a) / (1.0 + tan_t * tan_a);
    middle = 0.5 * (far_side + near_side) * u;
    half_size = vec2(0.5 * (far_side - near_side), depth * r * inversesqrt(depth * depth - r * r));
  } else {  // at the eye's plane: the outline is unbounded there, and the near plane clips it
    middle = c.xy;
    half_size = vec2(4.0 * r);
  }
  // 1 % beyond the exact outline, for the rasteriser's rounding.
  vec2 offset = 1.01 * (a_corner.x * half_size.x * u + a_corner.y * half_size.y * v);
  vec3 p = vec3(middle + offset, c.z);
  v_position = p;
  v_centre = c;
  v_radius = r;
  gl_Position = u_projection * vec4(p, 1.0);
}
)";

inline constexpr const char* kSphereQuadFragmentMain = R"(
in vec3 v_position;
void main() {
  shade_sphere_along(normalize(v_position));
}
)";

}  // namespace imasim::render::shaders
