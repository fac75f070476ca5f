// Heat maps from the command line: a recorded run writes its frame and one heat map per
// instrument, named in its side file; `imasim heatmap` pools recordings into one picture and
// refuses bad files with exit 2.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_process.hpp"

namespace {

using imasim::test::Finished;
using imasim::test::png_size;
using imasim::test::read_file;

const std::string kDir = ::testing::TempDir();
std::string err_file() {
  return imasim::test::test_err_file(kDir, "imasim_heatmap");
}
const std::string kScript = std::string(IMASIM_SOURCE_DIR) + "/examples/open_fascia.script";

Finished run(const std::string& args) {
  return imasim::test::run_imasim(args, err_file());
}

// The stem of one short recorded run per test: ctest runs these tests as parallel processes, and
// a shared file would be read by one while another rewrites it.
std::string run_stem() {
  return kDir + "imasim_heatmap_run_" +
         ::testing::UnitTest::GetInstance()->current_test_info()->name();
}

// The recorded run's trajectory (its files are inputs to the heatmap command).
const std::string& recorded() {
  static const std::string csv = [] {
    const std::string path = run_stem() + ".csv";
    const Finished r =
        run("run --headless --script " + kScript + " --seconds 1 --record " + path + " --json");
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return path;
  }();
  return csv;
}

TEST(RecordedRunHeatMaps, TheRunWritesItsFrameAndOneHeatMapPerInstrument) {
  recorded();
  const nlohmann::json side = nlohmann::json::parse(read_file(run_stem() + ".json"));
  ASSERT_TRUE(side["run"].contains("heat_maps")) << side["run"].dump(1);
  const nlohmann::json& maps = side["run"]["heat_maps"];
  EXPECT_EQ(maps["frame"], run_stem() + ".frame.json");
  EXPECT_EQ(maps["forceps"], run_stem() + ".heatmap-forceps.png");
  EXPECT_EQ(maps["hook"], run_stem() + ".heatmap-hook.png");
  for (const char* tool : {"forceps", "hook"})
    EXPECT_EQ(png_size(maps[tool]), (std::pair<unsigned, unsigned>{1100, 700})) << tool;
  const nlohmann::json frame = nlohmann::json::parse(read_file(maps["frame"]));
  EXPECT_EQ(frame["format"], "imasim heat map frame");
  EXPECT_EQ(frame["outlines"].size(), 3u);
  EXPECT_EQ(frame["centerline"].size(), 9u);
}

TEST(HeatmapCommand, PoolsRecordingsIntoOnePicture) {
  const std::string csv = recorded(), out = kDir + "imasim_heatmap_pooled.png";
  const Finished r = run("heatmap --trajectory " + csv + " --trajectory " + csv +
                         " --tool hook --frame " + run_stem() + ".frame.json --out " + out +
                         " --title 'Hook, two runs' --width 900 --height 600 --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["samples"], 122);  // 61 rows each
  EXPECT_EQ(j["recordings"], 2);
  EXPECT_GT(j["density_max_per_mm2"].get<double>(), 0);
  EXPECT_EQ(png_size(out), (std::pair<unsigned, unsigned>{900, 600}));
}

TEST(HeatmapCommand, BadFilesAreClearErrors) {
  const std::string csv = recorded(), frame = run_stem() + ".frame.json";
  const std::string bad_frame = kDir + "imasim_heatmap_bad_frame.json";
  std::string text = read_file(frame);
  text.replace(text.find("\"u\""), 3, "\"w\"");
  std::ofstream(bad_frame) << text;
  const Finished f = run("heatmap --trajectory " + csv + " --tool hook --frame " + bad_frame +
                         " --out " + kDir + "x.png");
  EXPECT_EQ(f.exit_code, 2);
  EXPECT_NE(f.err.find(bad_frame + ": key 'u': missing"), std::string::npos) << f.err;

  const std::string plain = kDir + "imasim_heatmap_plain.csv";
  std::ofstream(plain) << "t,x,y,z\n0,0,0,0\n0.1,0,zero,0\n";
  const Finished t =
      run("heatmap --trajectory " + plain + " --frame " + frame + " --out " + kDir + "x.png");
  EXPECT_EQ(t.exit_code, 2);
  EXPECT_NE(t.err.find(plain + ":3"), std::string::npos) << t.err;

  const Finished missing_tool =
      run("heatmap --trajectory " + csv + " --frame " + frame + " --out " + kDir + "x.png");
  EXPECT_EQ(missing_tool.exit_code, 2) << "the recorder's file has no t,x,y,z columns";

  const Finished over =
      run("heatmap --trajectory " + csv + " --tool hook --frame " + frame + " --out " + csv);
  EXPECT_EQ(over.exit_code, 4);
  EXPECT_NE(read_file(csv).find("t_s,"), std::string::npos) << "the input was overwritten";

  const Finished nowhere = run("heatmap --trajectory " + csv + " --tool hook --frame " + frame +
                               " --out " + kDir + "no_such_directory/x.png");
  EXPECT_EQ(nowhere.exit_code, 4);
  EXPECT_NE(nowhere.err.find("no_such_directory/x.png"), std::string::npos) << nowhere.err;

  const Finished tool = run("heatmap --trajectory " + csv + " --tool scalpel --frame " + frame +
                            " --out " + kDir + "x.png");
  EXPECT_NE(tool.exit_code, 0);
}

}  // namespace
