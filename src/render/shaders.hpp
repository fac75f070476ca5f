#pragma once
// GLSL 3.30 core sources of the renderer. Lighting is in camera space: the endoscope carries
// its own light, so the light sits at the eye (a headlight), as in a real scope.
namespace imasim::render::shaders {

// Shared lighting: Blinn-Phong with a narrow, strong highlight and a Fresnel rim (wet tissue
// reflects the scope's light sharply at grazing angles), coagulation browning, the cautery glow.
// Compiled in three variants (render/shader_variant.hpp), chosen by the two macros below. A
// branch on a uniform does not skip code on llvmpipe: it runs both sides for every pixel under
// a mask, so the glow's lighting, tested against a zero strength, cost a fifth of the surfaces'
// shading while the pedal was up (docs/PERFORMANCE.md, sixteenth entry).
inline constexpr const char* kLighting = R"(
uniform vec3 u_colour;
uniform float u_specular;
uniform float u_shininess;
#if IMASIM_GLOW
uniform vec3 u_glow_position; // camera space
uniform float u_glow;
#endif
vec3 shade_colour(vec3 p, vec3 n, float coagulation) {
#if IMASIM_KEY_COLOURS
  return u_colour;  // flat key colour, unlit
#else
  float distance2 = dot(p, p);
  float inv_distance = inversesqrt(distance2);
  vec3 v = -p * inv_distance;
  float facing = dot(n, v);
  facing = abs(facing);  // membranes are seen from both sides
  // The scope's light falls off with distance (its working range is a few centimetres).
  float light = 1.0 / (1.0 + 40.0 * distance2);
  vec3 base = mix(u_colour, vec3(0.42, 0.31, 0.22), 0.75 * coagulation);
  float wet = u_specular * (1.0 - 0.8 * coagulation);
  // With the light at the eye the half vector is v: the highlight is pow(n.v, shininess),
  // taken as (1 - shininess (1 - n.v) / 4)^4, which has the same slope at n.v = 1 and falls to
  // zero a little sooner: llvmpipe evaluates pow as a log and an exponential, each a polynomial,
  // and the two were an eighth of the frame (docs/PERFORMANCE.md).
  float spread = max(1.0 - 0.25 * u_shininess * (1.0 - facing), 0.0);
  spread *= spread;
  float highlight = spread * spread;
  float grazing = 1.0 - facing;
  float grazing2 = grazing * grazing;
  float fresnel = grazing2 * grazing2 * grazing;
  vec3 colour = base * (0.18 + 0.9 * facing * light) + vec3(wet * highlight * light)
                + 0.08 * fresnel * vec3(1.0, 0.9, 0.9);
#if IMASIM_GLOW
  vec3 to_glow = u_glow_position - p;
  float d2 = dot(to_glow, to_glow);
  float lit = max(dot(n, to_glow) * inversesqrt(max(d2, 1e-12)), 0.0);
  colour += u_glow * vec3(1.0, 0.55, 0.15) * (0.2 + lit) / (1.0 + d2 / 2.5e-5);
#endif
  return clamp(colour, 0.0, 1.0);
#endif
}
)";

inline constexpr const char* kSurfaceVertex = R"(#version 330 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec3 a_normal;
layout(location = 2) in float a_shade;
uniform mat4 u_view;
uniform mat4 u_projection;
out vec3 v_position;
out vec3 v_normal;
out float v_shade;
void main() {
  vec4 p = u_view * vec4(a_position, 1.0);
  v_position = p.xyz;
  v_normal = mat3(u_view) * a_normal;
  v_shade = a_shade;
  gl_Position = u_projection * p;
}
)";

inline constexpr const char* kSurfaceFragmentMain = R"(
in vec3 v_position;
in vec3 v_normal;
in float v_shade;
out vec4 o_colour;
void main() {
  // One reciprocal square root (a zero normal, of a degenerate triangle, stays zero: unlit).
  vec3 n = v_normal * inversesqrt(max(dot(v_normal, v_normal), 1e-24));
  o_colour = vec4(shade_colour(v_position, n, v_shade), 1.0);
}
)";

}  // namespace imasim::render::shaders
