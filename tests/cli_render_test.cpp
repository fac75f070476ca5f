// `imasim render` as a user runs it: frames of the scripted session written as PNG files of the
// size asked for, with the JSON summary; bad requests refused with their exit codes.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_process.hpp"

namespace {

using imasim::test::Finished;
using imasim::test::png_size;
using imasim::test::read_file;

const std::string kDir = ::testing::TempDir();
std::string err_file() {
  return imasim::test::test_err_file(kDir, "imasim_render");
}
const std::string kScript = std::string(IMASIM_SOURCE_DIR) + "/examples/open_fascia.script";

Finished run(const std::string& args) {
  return imasim::test::run_imasim(args, err_file());
}

TEST(RenderCommand, WritesTheFramesOfTheScriptedSession) {
  const std::string out = kDir + "imasim_render_frames";
  std::filesystem::remove_all(out);
  const Finished r =
      run("render --script " + kScript +
          " --frames 3 --fps 10 --width 240 --height 136 --camera orbit --out " + out + " --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["frames"], 3);
  EXPECT_NEAR(j["simulated_s"].get<double>(), 0.2, 0.0051);  // frames at 0, 0.1 and 0.2 s
  EXPECT_NE(j["renderer"].get<std::string>(), "");
  for (const char* name : {"frame_0000.png", "frame_0001.png", "frame_0002.png"}) {
    const auto [w, h] = png_size(out + "/" + name);
    EXPECT_EQ(w, 240u) << name;
    EXPECT_EQ(h, 136u) << name;
  }
  EXPECT_FALSE(std::filesystem::exists(out + "/frame_0003.png"));
  // The instruments move between frames: the pictures differ.
  EXPECT_NE(read_file(out + "/frame_0000.png"), read_file(out + "/frame_0002.png"));
}

TEST(RenderCommand, StereoModesWriteOneImageEach) {
  const std::string out = kDir + "imasim_render_stereo";
  for (const char* mode : {"side-by-side", "anaglyph"}) {
    std::filesystem::remove_all(out);
    const Finished r = run(std::string("render --frames 1 --width 200 --height 100 --stereo ") +
                           mode + " --out " + out);
    ASSERT_EQ(r.exit_code, 0) << mode << ": " << r.err;
    EXPECT_EQ(png_size(out + "/frame_0000.png"), (std::pair<unsigned, unsigned>{200, 100}));
  }
}

TEST(RenderCommand, BadRequestsAreClearErrors) {
  const std::string file = kDir + "imasim_render_not_a_dir";
  { std::ofstream(file) << "x"; }
  Finished r = run("render --frames 1 --out " + file + "/sub");
  EXPECT_EQ(r.exit_code, 4);
  EXPECT_NE(r.err.find("cannot make the directory"), std::string::npos) << r.err;
  r = run("render --frames 0 --out " + kDir + "imasim_render_x");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--frames"), std::string::npos) << r.err;
  r = run("render --frames 1 --fps nan --out " + kDir + "imasim_render_x");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--fps"), std::string::npos) << r.err;
  r = run("render --frames 1 --stereo sideways --out " + kDir + "imasim_render_x");
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("--stereo"), std::string::npos) << r.err;
  const std::string scene = kDir + "imasim_render_bad_scene.toml";
  { std::ofstream(scene) << "[solver]\nsubsteps = \"many\"\n"; }
  r = run("render --frames 1 --scene " + scene + " --out " + kDir + "imasim_render_x");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("imasim_render_bad_scene.toml:2"), std::string::npos) << r.err;
}

}  // namespace
