// libFuzzer target: scene files (TOML). Any bytes are either refused with SceneFileError or
// give a scene that prints as TOML and reads back to the same text (print_scene and parse_scene
// agree), never a crash, a hang or another exception.
#include <cstddef>
#include <cstdint>
#include <string>

#include "fuzz_check.hpp"
#include "scene/scene_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace imasim::scene;
  const std::string text(reinterpret_cast<const char*>(data), size);
  ThoraxSceneParams params;
  try {
    params = parse_scene(text, "fuzz.toml");
  } catch (const SceneFileError& e) {
    imasim::fuzz::require(!e.messages().empty(), "a SceneFileError with no message");
    return 0;
  }
  // An accepted scene survives its own printed form.
  const std::string printed = print_scene(params);
  std::string reprinted;
  try {
    reprinted = print_scene(parse_scene(printed, "printed.toml"));
  } catch (const SceneFileError& e) {
    imasim::fuzz::fail("the printed form of an accepted scene is refused: " + e.messages().front());
  }
  imasim::fuzz::require(reprinted == printed, "print -> parse -> print changes the scene");
  return 0;
}
