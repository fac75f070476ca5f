#pragma once
// `imasim scene print-default` writes the built-in scene as TOML; `imasim scene check FILE`
// validates a scene file and lists every problem with its file, line and key.
#include <CLI/CLI.hpp>
#include <memory>
#include <string>

namespace imasim::cli {

struct SceneOptions {
  CLI::App* print_default = nullptr;
  CLI::App* check = nullptr;
  std::string file;
};

std::shared_ptr<SceneOptions> add_scene_command(CLI::App& app);

// Exit code: 0 ok, 1 the file has errors.
int run_scene_command(const SceneOptions& options);

}  // namespace imasim::cli
