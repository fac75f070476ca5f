// The window under Xvfb: `imasim window` opens, plays the example script for two
// seconds of simulated time, saves a screenshot that is the size asked for and not blank, and
// quits with no OpenGL error; Escape, pressed through the window's key handler, quits it; two
// emulated haptic devices drive it over OpenIGTLink; with no display or a bad scene it says so
// and exits 2. Skipped only where xvfb-run is missing.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>

#include "cli_process.hpp"
#include "render/image_file.hpp"

namespace imasim::test {
namespace {

const std::string kExe = IMASIM_EXE;
const std::string kSource = IMASIM_SOURCE_DIR;

bool have_xvfb() {
  return std::system("command -v xvfb-run > /dev/null 2>&1") == 0;
}

std::string scratch() {
  const std::string dir = testing::TempDir() + "imasim_window/";
  std::filesystem::create_directories(dir);
  return dir;
}

// `imasim window ARGS` on a virtual 1280 x 800 screen.
Finished run_window(const std::string& args) {
  const std::string err = test_err_file(scratch(), "window");
  return run_shell(
      "xvfb-run -a -s '-screen 0 1280x800x24' " + kExe + " window " + args + " --json 2> " + err,
      err);
}

// Standard deviation of the grey level over a region (0..255).
double grey_spread(const render::RgbImage& image, int x0, int x1) {
  double sum = 0, sum2 = 0, n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = x0; x < x1; ++x) {
      const std::size_t i = 3 * (std::size_t(y) * std::size_t(image.width) + std::size_t(x));
      const double g = (image.rgb[i] + image.rgb[i + 1] + image.rgb[i + 2]) / 3.0;
      sum += g;
      sum2 += g * g;
      n += 1;
    }
  return std::sqrt(std::max(0.0, sum2 / n - (sum / n) * (sum / n)));
}

TEST(WindowSmoke, PlaysTheScriptAndSavesANonBlankScreenshot) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not found (apt install xvfb xauth)";
  const std::string png = scratch() + "two_seconds.png";
  std::filesystem::remove(png);
  const Finished f = run_window("--script " + kSource +
                                "/examples/open_fascia.script --seconds 2 --screenshot " + png);
  ASSERT_EQ(f.exit_code, 0) << f.out << f.err;
  const auto j = nlohmann::json::parse(f.out);
  EXPECT_EQ(j["quit"], "finished");
  EXPECT_EQ(j["gl_errors"], 0) << f.err;
  EXPECT_EQ(f.err.find("OpenGL error"), std::string::npos) << f.err;
  EXPECT_NEAR(j["simulated_s"].get<double>(), 2.0, 1e-6);
  EXPECT_GT(j["frames"].get<int>(), 2);
  EXPECT_GT(j["score"]["fascia_edges_cut"].get<int>(), 0) << "the script's cut shows in the card";
  EXPECT_EQ(j["screenshot"], png);
  const render::RgbImage image = render::read_png(png);
  EXPECT_EQ(image.width, 1280);
  EXPECT_EQ(image.height, 720);
  // The 3D view (left of the panels' 360 pixel column) and the whole image have structure.
  EXPECT_GT(grey_spread(image, 0, image.width), 10);
  EXPECT_GT(grey_spread(image, 0, image.width - 360), 5);
}

TEST(WindowSmoke, EscapeQuits) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not found (apt install xvfb xauth)";
  // No end time: only the key can end it (the test's timeout would otherwise).
  const std::string png = scratch() + "escape.png";
  const Finished f = run_window("--quit-key-after 1.5 --orbit --stereo anaglyph --screenshot " +
                                png + " --width 800 --height 600");
  ASSERT_EQ(f.exit_code, 0) << f.out << f.err;
  const auto j = nlohmann::json::parse(f.out);
  EXPECT_EQ(j["quit"], "key");
  EXPECT_EQ(j["input"], "keyboard");
  EXPECT_EQ(j["gl_errors"], 0) << f.err;
  EXPECT_GT(j["simulated_s"].get<double>(), 0);
  const render::RgbImage image = render::read_png(png);
  EXPECT_EQ(image.width, 800);
  EXPECT_EQ(image.height, 600);
  EXPECT_GT(grey_spread(image, 0, image.width - 360), 5);
}

TEST(WindowSmoke, SideBySideStereoDrawsWithoutErrors) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not found (apt install xvfb xauth)";
  const Finished f = run_window("--script " + kSource +
                                "/examples/open_fascia.script --seconds 0.3 --stereo side-by-side");
  ASSERT_EQ(f.exit_code, 0) << f.out << f.err;
  EXPECT_EQ(nlohmann::json::parse(f.out)["gl_errors"], 0) << f.err;
}

// The window with two emulated haptic devices (`imasim device-emulator`, a child process playing
// the example script) over OpenIGTLink on loopback: the 1 kHz loop runs beside the window and
// renders a force, and the devices' hands do the script's work (strands cut).
TEST(WindowSmoke, EmulatedHapticDevicesDriveTheInstrumentsOverOpenIgtLink) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not found (apt install xvfb xauth)";
  const Finished f = run_window("--devices emulator --script " + kSource +
                                "/examples/open_fascia.script --seconds 3");
  ASSERT_EQ(f.exit_code, 0) << f.out << f.err;
  const nlohmann::json report = nlohmann::json::parse(f.out);
  EXPECT_EQ(report["input"], "emulator");
  EXPECT_EQ(report["gl_errors"], 0);
  ASSERT_TRUE(report.contains("haptic_loop")) << f.out;
  EXPECT_GT(report["haptic_loop"]["ticks"].get<double>(), 1000) << "the loop ran for seconds";
  EXPECT_GT(report["haptic_loop"]["force_max_n"].get<double>(), 0) << "a contact pushed back";
  EXPECT_GT(report["score"]["strands_cut"].get<int>(), 0) << "the hook cut, driven by a device";
}

// Real X key events (xdotool, when installed): F8 records, L moves the right hand (the hook)
// right for a second, R closes the forceps' jaws, F8 stops, Escape quits.
TEST(WindowSmoke, RealKeysDriveTheInstruments) {
  if (!have_xvfb()) GTEST_SKIP() << "xvfb-run not found (apt install xvfb xauth)";
  if (std::system("command -v xdotool > /dev/null 2>&1") != 0)
    GTEST_SKIP() << "xdotool not found (apt install xdotool): real key events not tested";
  const std::string csv = scratch() + "keys.csv";
  std::filesystem::remove(csv);
  const std::string err = test_err_file(scratch(), "window");
  const std::string keys =
      "xdotool search --sync --name imasim windowfocus --sync; sleep 1; xdotool key F8; "
      "sleep 0.3; xdotool keydown l; sleep 1; xdotool keyup l; xdotool keydown r; sleep 0.6; "
      "xdotool keyup r; sleep 0.5; xdotool key F8; sleep 0.3; xdotool key Escape";
  const Finished f = run_shell("xvfb-run -a -s '-screen 0 1280x800x24' sh -c '" + kExe +
                                   " window --json --record " + csv + " & pid=$!; " + keys +
                                   "; wait $pid' 2> " + err,
                               err);
  ASSERT_EQ(f.exit_code, 0) << f.out << f.err;
  EXPECT_EQ(nlohmann::json::parse(f.out)["quit"], "key");
  const std::vector<std::string> lines = lines_of(read_file(csv));
  ASSERT_GT(lines.size(), 30u) << "about 2 s of rows at 60 Hz";
  // Columns by name from the header.
  const auto column = [&](const std::string& name) {
    std::size_t index = 0, at = 0;
    const std::string& header = lines[0];
    while (header.compare(at, name.size() + 1, name + ",") != 0) {
      at = header.find(',', at);
      if (at == std::string::npos) return std::size_t(-1);
      ++at;
      ++index;
    }
    return index;
  };
  const auto value = [&](const std::string& line, std::size_t index) {
    std::stringstream s(line);
    std::string cell;
    for (std::size_t k = 0; k <= index; ++k)
      std::getline(s, cell, ',');
    return std::stod(cell);
  };
  const std::size_t hook_x = column("hook_device_x"), jaw = column("forceps_jaw_rad");
  ASSERT_NE(hook_x, std::size_t(-1));
  ASSERT_NE(jaw, std::size_t(-1));
  // A second at 3 cm/s of the hand, scaled 3:1 by the arm: about 1 cm of the instrument.
  const double moved = value(lines.back(), hook_x) - value(lines[1], hook_x);
  EXPECT_GT(moved, 0.006) << "the L key moved the hook's device pose right";
  EXPECT_LT(moved, 0.016);
  EXPECT_LT(value(lines.back(), jaw), value(lines[1], jaw) - 0.2) << "R closed the forceps";
}

TEST(WindowSmoke, NoDisplayOrABadSceneIsAClearErrorNotACrash) {
  const std::string err = test_err_file(scratch(), "window");
  Finished f = run_shell("env -u DISPLAY -u WAYLAND_DISPLAY " + kExe + " window 2> " + err, err);
  EXPECT_EQ(f.exit_code, 2);
  EXPECT_NE(f.err.find("no display"), std::string::npos) << f.err;
  f = run_shell("env -u DISPLAY -u WAYLAND_DISPLAY " + kExe + " 2> " + err, err);
  EXPECT_EQ(f.exit_code, 2);
  EXPECT_NE(f.err.find("imasim run --headless"), std::string::npos) << f.err;
  // A display that cannot be opened (set, but no server there).
  f = run_shell("DISPLAY=:9876 " + kExe + " window 2> " + err, err);
  EXPECT_EQ(f.exit_code, 2);
  EXPECT_NE(f.err.find("cannot open a window"), std::string::npos) << f.err;
  if (!have_xvfb()) return;
  const std::string scene = scratch() + "bad.toml";
  { std::ofstream(scene) << "[anatomy]\nno_such_key = 1\n"; }
  f = run_window("--scene " + scene);
  EXPECT_EQ(f.exit_code, 2) << f.out;
  EXPECT_NE(f.err.find("no_such_key"), std::string::npos) << f.err;
}

}  // namespace
}  // namespace imasim::test
