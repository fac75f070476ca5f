#include "render/shader_variant.hpp"

namespace imasim::render {

std::string variant_fragment_source(ShaderVariant variant, const std::string& body) {
  const bool glow = variant == ShaderVariant::lit_with_glow;
  const bool key = variant == ShaderVariant::key_colours;
  return std::string("#version 330 core\n#define IMASIM_GLOW ") + (glow ? "1" : "0") +
         "\n#define IMASIM_KEY_COLOURS " + (key ? "1" : "0") + "\n" + body;
}

}  // namespace imasim::render
