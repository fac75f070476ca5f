#pragma once
// Scene files (TOML): every key of scene_keys.hpp, defaulting to the built-in scene, validated
// on load. Errors name the file, the line and the key ("scene.toml:12: key 'heart.twist_rad':
// ..."); an unknown key is an error that suggests the nearest valid key.
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/thorax_scene.hpp"

namespace imasim::scene {

class SceneFileError : public std::runtime_error {
 public:
  explicit SceneFileError(std::vector<std::string> messages);
  const std::vector<std::string>& messages() const { return messages_; }

 private:
  std::vector<std::string> messages_;
};

// Parses TOML text; `name` is the file name used in messages. Throws SceneFileError listing
// every problem found. Keys not in the text keep their built-in defaults.
ThoraxSceneParams parse_scene(const std::string& text, const std::string& name);

// Reads and parses a file (a missing or unreadable file is a SceneFileError too).
ThoraxSceneParams load_scene_file(const std::string& path);

// The scene as TOML: every key with its value and a comment (meaning, unit, source).
std::string print_scene(const ThoraxSceneParams& params);

}  // namespace imasim::scene
