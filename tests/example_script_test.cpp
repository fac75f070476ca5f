// The example script built into the program (apps/imasim/example_script.hpp) is the file in
// examples/ byte for byte, and plays as it does.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "example_script.hpp"

namespace {

std::string read_example() {
  std::ifstream in(IMASIM_SOURCE_DIR "/examples/open_fascia.script", std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(ExampleScript, IsTheFileInExamplesByteForByte) {
  const std::string file = read_example();
  ASSERT_FALSE(file.empty());
  EXPECT_EQ(std::string(imasim::cli::example_script_text()), file);
}

TEST(ExampleScript, AnEmptyPathLoadsTheBuiltInScriptAsTheFileLoads) {
  const imasim::surgery::InputScript built_in = imasim::cli::load_script_or_example("");
  const imasim::surgery::InputScript file =
      imasim::surgery::load_input_script(IMASIM_SOURCE_DIR "/examples/open_fascia.script");
  EXPECT_GT(built_in.end_time(), 5.0);  // the example runs 9.8 s
  EXPECT_EQ(built_in.end_time(), file.end_time());
  EXPECT_EQ(built_in.left.poses.size(), file.left.poses.size());
  EXPECT_EQ(built_in.right.pedal.size(), file.right.pedal.size());
}

TEST(ExampleScript, AGivenPathIsLoadedAndAMissingOneNamed) {
  try {
    imasim::cli::load_script_or_example("/nonexistent/imasim.script");
    FAIL() << "a missing script must be an error";
  } catch (const imasim::surgery::InputScriptError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/imasim.script"), std::string::npos)
        << e.what();
  }
}

}  // namespace
