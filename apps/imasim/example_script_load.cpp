#include "example_script.hpp"

namespace imasim::cli {

surgery::InputScript load_script_or_example(const std::string& path) {
  if (!path.empty()) return surgery::load_input_script(path);
  return surgery::parse_input_script(example_script_text(), std::string(kExampleScriptName));
}

}  // namespace imasim::cli
