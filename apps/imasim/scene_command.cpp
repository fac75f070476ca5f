#include "scene_command.hpp"

#include <iostream>

#include "cli_checks.hpp"

#include "scene/scene_file.hpp"

namespace imasim::cli {

std::shared_ptr<SceneOptions> add_scene_command(CLI::App& app) {
  auto opt = std::make_shared<SceneOptions>();
  CLI::App* cmd = app.add_subcommand("scene", "Scene files: print the default, check a file");
  cmd->require_subcommand(1);
  opt->print_default = cmd->add_subcommand("print-default", "Write the built-in scene as TOML");
  opt->check = cmd->add_subcommand("check", "Validate a scene file");
  opt->check->add_option("FILE", opt->file, "Scene file (TOML)")->required()->check(non_empty());
  return opt;
}

int run_scene_command(const SceneOptions& o) {
  if (*o.print_default) {
    std::cout << scene::print_scene(scene::default_thorax_scene_params());
    return 0;
  }
  scene::ThoraxSceneParams params;
  try {
    params = scene::load_scene_file(o.file);
  } catch (const scene::SceneFileError& e) {
    for (const std::string& m : e.messages())
      std::cerr << m << '\n';
    return 1;
  }
  // What `run` does next: build the scene, so a file that passes here also starts there.
  try {
    for (const std::string& note : scene::make_thorax_scene(params).setup_notes) {
      if (note.starts_with(o.file + ":"))  // the file's own, at its line
        std::cout << "note: " << note << '\n';
      else
        std::cout << o.file << ": note: " << note << '\n';
    }
  } catch (const std::exception& e) {
    std::cerr << o.file << ": the scene cannot be built: " << e.what() << '\n';
    return 1;
  }
  std::cout << o.file << ": ok\n";
  return 0;
}

}  // namespace imasim::cli
