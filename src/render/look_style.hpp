#pragma once
// Each look's colour and gloss (lit), and its key colour (flat, for tests and picking).
#include <array>
#include <cstdint>

#include "render/render_frame.hpp"

namespace imasim::render {

struct LookStyle {
  std::array<float, 3> colour;  // linear RGB, 0..1
  float specular;               // highlight strength
  float shininess;              // Blinn-Phong exponent: wet tissue is sharp and bright
};

LookStyle look_style(Look look);

}  // namespace imasim::render
