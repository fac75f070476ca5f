#include "command_inputs.hpp"

#include <iostream>

#include "scene/scene_file.hpp"

namespace imasim::cli {

bool load_scene_params(const std::string& file, scene::ThoraxSceneParams& out) {
  if (file.empty()) {
    out = scene::default_thorax_scene_params();
    return true;
  }
  try {
    out = scene::load_scene_file(file);
    return true;
  } catch (const scene::SceneFileError& e) {
    for (const std::string& m : e.messages())
      std::cerr << m << '\n';
    return false;
  }
}

bool load_script(const std::string& file, std::optional<surgery::InputScript>& out) {
  out.reset();
  if (file.empty()) return true;
  try {
    out = surgery::load_input_script(file);
    return true;
  } catch (const surgery::InputScriptError& e) {
    std::cerr << e.what() << '\n';
    return false;
  }
}

}  // namespace imasim::cli
