#pragma once
// The compiled variants of the renderer's lighting (shaders.hpp: kLighting). llvmpipe runs both
// sides of a branch on a uniform for every pixel, so what a uniform used to switch on or off is
// chosen when the program is compiled instead: the cautery's glow only while it glows, the
// flat key colours only for the tests that find tissues by colour.
#include <cstddef>
#include <cstdint>
#include <string>

namespace imasim::render {

enum class ShaderVariant : std::uint8_t {
  lit,            // the surgeon's picture with the pedal up
  lit_with_glow,  // the same with the electrode's glow as a point light
  key_colours,    // each look's flat key colour, unlit
};
inline constexpr std::size_t kShaderVariantCount = 3;

// A fragment source for the variant: the #version line, the macros that select it, then `body`.
std::string variant_fragment_source(ShaderVariant variant, const std::string& body);

}  // namespace imasim::render
