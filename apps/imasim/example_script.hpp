#pragma once
// The example session's input script (examples/open_fascia.script), built into the program so
// that the commands that play it by default (haptics-bench, device-emulator) need no source tree.
#include <string>
#include <string_view>

#include "surgery/input_script.hpp"

namespace imasim::cli {

// The name the built-in script goes by in messages and reports.
inline constexpr std::string_view kExampleScriptName = "examples/open_fascia.script (built in)";

// The text of examples/open_fascia.script when the program was built.
std::string_view example_script_text();

// The script at `path`, or the built-in example when `path` is empty.
surgery::InputScript load_script_or_example(const std::string& path);

}  // namespace imasim::cli
