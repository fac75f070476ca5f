#pragma once
// The inputs several subcommands read the same way (run, render, window): a scene file and an
// input script, their errors printed as the loaders give them (file, line, key).
#include <optional>
#include <string>

#include "scene/thorax_scene.hpp"
#include "surgery/input_script.hpp"

namespace imasim::cli {

// The scene file's parameters, or the built-in scene's when `file` is empty; false after
// printing the file's errors to stderr.
bool load_scene_params(const std::string& file, scene::ThoraxSceneParams& out);

// The input script, or none when `file` is empty; false after printing its error to stderr.
bool load_script(const std::string& file, std::optional<surgery::InputScript>& out);

}  // namespace imasim::cli
