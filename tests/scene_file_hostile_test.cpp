// Scene files from the red team's hostile set: each is refused quickly with a
// file:line message, never a crash (deep nesting overflowed toml++'s recursion), a hang (the
// "did you mean" search over megabyte keys or thousands of unknown keys) or a silent accept.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string_view>

#include "mesh_writers.hpp"
#include "scene/scene_file.hpp"

namespace imasim::scene {
namespace {

// The messages of parsing `text`, failing the test if it is accepted or hangs (see below).
std::vector<std::string> refused(const std::string& text) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::string> messages;
  try {
    parse_scene(text, "bad.toml");
    ADD_FAILURE() << "accepted: " << text.substr(0, 200);
  } catch (const SceneFileError& e) {
    messages = e.messages();
  }
  // A hang guard, not a benchmark: what it guards against (a search or a parse that grows with
  // the hostile input) takes minutes, so the bound stays far from the sanitizers' and a loaded
  // machine's slowdown (1.1 s once under ASan beside a build).
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
  return messages;
}

// Pieces appended in order (GCC 12 warns falsely on "literal" + std::string).
std::string cat(std::initializer_list<std::string_view> pieces) {
  std::string out;
  for (std::string_view p : pieces)
    out += p;
  return out;
}

std::string repeated(const std::string& s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i)
    out += s;
  return out;
}

void expect_first(const std::string& text, const std::string& message) {
  const std::vector<std::string> m = refused(text);
  ASSERT_FALSE(m.empty());
  EXPECT_NE(m[0].find(message), std::string::npos) << m[0].substr(0, 400);
}

TEST(SceneFileHostile, DeepNestingIsRefusedBeforeToml) {
  expect_first(cat({"a", repeated(".a", 20000), " = 1\n"}),
               "bad.toml:1: a dotted key deeper than 32 levels");
  expect_first(cat({"[heart]\n[", repeated("a.", 20000), "a]\n"}),
               "bad.toml:2: a dotted key deeper than 32 levels");
  expect_first(cat({"x = ", repeated("[", 20000), "\n"}),
               "bad.toml:1: tables or arrays nested deeper than 32 levels");
  expect_first(cat({"x = ", repeated("{a = ", 20000), "\n"}),
               "bad.toml:1: tables or arrays nested deeper than 32 levels");
  // Dots and brackets inside strings and comments are no nesting.
  expect_first(cat({"# ", repeated("a.[", 100), "\n[heart]\nphase_files = [\"/nonexistent/",
                    repeated("a.[", 100), "\", '/x/", repeated(".", 100), "']\n"}),
               "bad.toml:3: key 'heart.phase_files': /nonexistent/a.[a.[");
  // Nesting within the limit still gets the key's own message.
  expect_first(cat({"[heart]\n", repeated("a.", 10), "a = 1\n"}),
               "bad.toml:2: key 'heart.a': unknown");
}

TEST(SceneFileHostile, LongAndManyUnknownKeysAreReportedBounded) {
  // A 4 MB key: echoed cut to 80 bytes, no suggestion searched.
  const std::vector<std::string> m =
      refused(cat({"[heart]\n", repeated("k", 4'000'000), " = 1\n"}));
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0], cat({"bad.toml:2: key 'heart.", repeated("k", 74), "...': unknown key"}));
  // 30,000 unknown keys of 60 bytes: the first 20 listed with suggestions, the rest counted.
  std::string many = "[heart]\n";
  for (int i = 0; i < 30000; ++i)
    many += "heart_rate_" + std::to_string(100000 + i) + repeated("x", 40) + " = 1\n";
  const std::vector<std::string> listed = refused(many);
  ASSERT_EQ(listed.size(), 21u);
  EXPECT_NE(listed[0].find("bad.toml:2: key 'heart.heart_rate_100000"), std::string::npos);
  EXPECT_NE(listed[0].find("unknown key; did you mean 'heart."), std::string::npos) << listed[0];
  EXPECT_EQ(listed[20], "bad.toml: 29980 more problems not listed (the first 20 are above)");
}

TEST(SceneFileHostile, ControlCharactersInKeysAreEscaped) {
  const std::vector<std::string> m =
      refused("[heart]\n\"\\u001b[2J\\u0007red\" = 1\n");  // TOML escapes
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].find('\x1b'), std::string::npos);
  EXPECT_NE(m[0].find("key 'heart.\\x1b[2J\\x07red': unknown key"), std::string::npos) << m[0];
}

TEST(SceneFileHostile, AbsurdPositionsNameTheirKey) {
  expect_first("[anatomy]\nheart_offset_m = [1000, 0, 0]\n",
               "bad.toml:2: key 'anatomy.heart_offset_m': expected [x, y, z], three numbers in "
               "[-0.25, 0.25]");
  expect_first("[anatomy]\nsternum_position_m = [1e200, 0, 0]\n",
               "bad.toml:2: key 'anatomy.sternum_position_m': expected [x, y, z], three numbers "
               "in [-1, 1]");
  expect_first("[heart]\nmesh_translation_m = [0, 0, 1e300]\n",
               "bad.toml:2: key 'heart.mesh_translation_m'");
  expect_first("[ports]\ncamera_m = [0, 5, 0]\n", "bad.toml:2: key 'ports.camera_m'");
  expect_first("[heart]\nlong_axis = [1e300, 0, 1]\n", "bad.toml:2: key 'heart.long_axis'");
}

TEST(SceneFileHostile, ScenesTooCostlyToStepAreRefused) {
  expect_first("[solver]\nsubsteps = 512\niterations = 2\n",
               "bad.toml:2: key 'solver.substeps': substeps x iterations = 512 x 2 = 1024 sweeps "
               "per step, above the limit of 512");
  expect_first("[solver]\nsubsteps = 1000\n", "expected an integer in [1, 512], got 1000");
  expect_first("[fascia]\nnx = 1024\nny = 1024\n",
               "bad.toml:2: key 'fascia.nx': the scene would have up to ");
  expect_first("[vessel]\nfine_rings = 16384\nfine_segments = 256\n",
               "bad.toml:2: key 'vessel.fine_rings': the scene would have up to ");
  expect_first("[solver]\nsubsteps = 256\n[fascia]\nnx = 60\nny = 60\n",
               "bad.toml:4: key 'fascia.nx': substeps x iterations = 256 x 1 = 256 sweeps per "
               "step over up to 46938 particles: 12016128 particle sweeps per step, above the "
               "limit of 8000000");
}

TEST(SceneFileHostile, OnlyBoundedRegularFilesAreRead) {
  const test::TestFolder dir;
  const auto expect_load_error = [](const std::string& path, const std::string& message) {
    try {
      load_scene_file(path);
      ADD_FAILURE() << "accepted " << path;
    } catch (const SceneFileError& e) {
      EXPECT_EQ(std::string(e.what()), message);
    }
  };
  expect_load_error(
      dir.path().string(),
      dir.path().string() + ": cannot open the scene file: is a directory, not a file");
  expect_load_error("/dev/zero",
                    "/dev/zero: cannot open the scene file: not a regular file (a device or a "
                    "pipe is not read)");
  const std::string big = (dir / "big.toml").string();
  std::ofstream(big) << "# a scene\n";
  std::filesystem::resize_file(big, (1 << 20) + 1);  // sparse: nothing is written
  expect_load_error(big, big + ": the scene file is 1048577 bytes, above the limit of 1 MiB");
}

}  // namespace
}  // namespace imasim::scene
