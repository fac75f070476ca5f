// The study's report in a real browser (ctest label "browser"): Debian's headless Chromium loads
// the page with no console message (the page logs only on a broken image), the page's script marks
// it ready once every image has loaded with a size (and marks an error when one does not decode),
// and the screenshot shows the heat maps: their colours are counted in its pixels.
#include <cairo.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "report/study_files.hpp"
#include "report/study_summary.hpp"
#include "study_fixtures.hpp"

namespace {

using imasim::test::kHeatHigh;
using imasim::test::kHeatLow;

// One folder per test: ctest runs the tests as parallel processes, and two Chromiums on one
// profile refuse to start (its SingletonLock), as two writers of one report would collide.
std::string test_dir() {
  return ::testing::TempDir() + "imasim_browser_" +
         ::testing::UnitTest::GetInstance()->current_test_info()->name() + "/";
}

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Chromium as the test runs it: headless, no sandbox (root in a container), no GPU, its own
// profile, a fixed scale; chromium's own messages go to `err`.
int chromium(const std::string& args, const std::string& out, const std::string& err) {
  const std::string command =
      "timeout 120 chromium --headless --no-sandbox --disable-gpu --hide-scrollbars "
      "--force-device-scale-factor=1 --user-data-dir=" +
      test_dir() + "profile --enable-logging=stderr --v=0 --virtual-time-budget=5000 " + args +
      " >" + out + " 2>" + err;
  return std::system(command.c_str());
}

// The Table 1 study's report; with `decodable` false its heat map is a PNG signature followed by
// bytes that do not decode, which passes the report's own check.
std::string write_report(bool decodable = true) {
  const std::string dir = test_dir();
  std::filesystem::create_directories(dir);
  const std::string png = dir + "heat_map.png";
  if (decodable)
    imasim::test::write_heat_map_png(png);
  else
    std::ofstream(png, std::ios::binary) << "\x89PNG\r\n\x1a\n" << std::string(64, 'x');
  const std::vector<imasim::report::TrialResult> trials = imasim::test::table1_trials(png);
  const imasim::report::StudyInfo info = imasim::test::table1_info();
  const imasim::report::StudySummary summary = imasim::report::summarize_study(info.modes, trials);
  return imasim::report::write_study_files(dir, info, trials, summary).report_html;
}

bool near(const unsigned char* rgb, const unsigned char* want) {
  for (int k = 0; k < 3; ++k)
    if (std::abs(int(rgb[k]) - int(want[k])) > 6) return false;
  return true;
}

TEST(BrowserReport, LoadsWithoutConsoleMessagesAndMarksItselfReady) {
  const std::string page = write_report();
  ASSERT_EQ(chromium("--dump-dom file://" + page, test_dir() + "dom.html", test_dir() + "dom.err"),
            0)
      << slurp(test_dir() + "dom.err");
  const std::string dom = slurp(test_dir() + "dom.html");
  EXPECT_NE(dom.find("data-ready=\"yes\""), std::string::npos) << dom.substr(0, 400);
  EXPECT_NE(dom.find("0.589 ± 0.030"), std::string::npos);
  const std::string log = slurp(test_dir() + "dom.err");
  EXPECT_EQ(log.find(":CONSOLE"), std::string::npos) << log;
}

// The ready mark can fail: an image that does not decode gives "image-error" and a console error.
TEST(BrowserReport, AnImageThatDoesNotDecodeMarksThePageWithAnErrorInstead) {
  const std::string page = write_report(false);
  const std::string dir = test_dir();
  ASSERT_EQ(chromium("--dump-dom file://" + page, dir + "dom.html", dir + "dom.err"), 0)
      << slurp(dir + "dom.err");
  const std::string dom = slurp(dir + "dom.html");
  EXPECT_NE(dom.find("data-ready=\"image-error\""), std::string::npos) << dom.substr(0, 400);
  EXPECT_EQ(dom.find("data-ready=\"yes\""), std::string::npos);
  EXPECT_NE(slurp(dir + "dom.err").find(":CONSOLE"), std::string::npos);
}

TEST(BrowserReport, TheScreenshotShowsTheHeatMaps) {
  const std::string page = write_report();
  const std::string shot = test_dir() + "report.png";
  std::remove(shot.c_str());
  ASSERT_EQ(chromium("--window-size=1280,7000 --screenshot=" + shot + " file://" + page,
                     test_dir() + "shot.out", test_dir() + "shot.err"),
            0)
      << slurp(test_dir() + "shot.err");
  cairo_surface_t* image = cairo_image_surface_create_from_png(shot.c_str());
  ASSERT_EQ(cairo_surface_status(image), CAIRO_STATUS_SUCCESS) << shot;
  const int w = cairo_image_surface_get_width(image), h = cairo_image_surface_get_height(image);
  const int stride = cairo_image_surface_get_stride(image);
  const unsigned char* data = cairo_image_surface_get_data(image);
  long low = 0, high = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      // ARGB32 in native byte order (little-endian here): B, G, R, A.
      const unsigned char* p = data + y * stride + x * 4;
      const unsigned char rgb[3] = {p[2], p[1], p[0]};
      low += near(rgb, kHeatLow) ? 1 : 0;
      high += near(rgb, kHeatHigh) ? 1 : 0;
    }
  }
  cairo_surface_destroy(image);
  // Four heat maps (two groups, two instruments), each 400 x 300 px: half of each colour.
  EXPECT_GE(low, 4 * 400 * 150 * 95 / 100) << shot;
  EXPECT_GE(high, 4 * 400 * 150 * 95 / 100) << shot;
  EXPECT_LE(low, 4 * 400 * 150 + 1000) << shot;
}

}  // namespace
