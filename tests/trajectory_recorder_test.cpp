// The session recorder (metrics/trajectory_recorder.hpp): one field per column in every line, a
// row at each 1/60 s with 5 ms steps, the side file naming every column with its unit, and rows
// on disk at the first flush.
#include "metrics/trajectory_recorder.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace imasim::metrics {
namespace {

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream s(line);
  for (std::string f; std::getline(s, f, ',');)
    out.push_back(f);
  return out;
}

TrajectorySample example() {
  TrajectorySample s;
  s.time = 1.25;
  s.tools[0].tip = Vec3(0.01, -0.02, 0.03);
  s.tools[0].jaw_angle = Real(0.5);
  s.tools[0].clutch = true;
  s.tools[0].contact = surgery::Tissue::fascia;
  s.tools[1].force_normal = Real(1.5);
  s.tools[1].force_thermal = Real(0.25);
  s.tools[1].orientation = {0, 1, 0, 0};
  s.pedal = surgery::PedalMode::coag;
  s.power_w = 40;
  return s;
}

TEST(TrajectoryRecorder, EveryLineHasAFieldPerColumnInTheColumnsOrder) {
  const std::vector<TrajectoryColumn> columns = trajectory_columns();
  const std::string header = trajectory_csv_header();
  ASSERT_EQ(header.back(), '\n');
  const std::vector<std::string> names = fields(header.substr(0, header.size() - 1));
  ASSERT_EQ(names.size(), columns.size());
  for (std::size_t k = 0; k < names.size(); ++k)
    EXPECT_EQ(names[k], columns[k].name);
  const std::string line = trajectory_csv_line(example());
  const std::vector<std::string> f = fields(line.substr(0, line.size() - 1));
  ASSERT_EQ(f.size(), names.size());
  auto at = [&](const std::string& name) {
    for (std::size_t k = 0; k < names.size(); ++k)
      if (names[k] == name) return f[k];
    ADD_FAILURE() << "no column " << name;
    return std::string();
  };
  EXPECT_EQ(at("t_s"), "1.25");
  EXPECT_EQ(at("forceps_y"), "-0.02");
  EXPECT_EQ(at("forceps_jaw_rad"), "0.5");
  EXPECT_EQ(at("forceps_clutch"), "1");
  EXPECT_EQ(at("forceps_contact"), "fascia");
  EXPECT_EQ(at("hook_force_normal_n"), "1.5");
  EXPECT_EQ(at("hook_force_thermal_n"), "0.25");
  EXPECT_EQ(at("hook_qx"), "1");
  EXPECT_EQ(at("hook_contact"), "none");
  EXPECT_EQ(at("pedal"), "coag");
  EXPECT_EQ(at("power_w"), "40");
  // Nothing a plain CSV reader would need options for: no quotes, no spaces, no semicolons.
  EXPECT_EQ(line.find_first_of("\"; "), std::string::npos) << line;
}

TEST(TrajectoryRecorder, SixtyRowsASecondWithFiveMillisecondSteps) {
  const std::string path = ::testing::TempDir() + "imasim_trajectory_rate.csv";
  TrajectoryRecorder r{OutputFile(path, "the trajectory file")};
  TrajectorySample s;
  std::vector<double> times;
  for (int step = 0; step <= 2000; ++step) {  // 0 to 10 s
    s.time = step * 0.005;
    if (r.due(s.time)) {
      r.record(s);
      times.push_back(s.time);
    }
  }
  r.finish();
  EXPECT_EQ(r.rows(), 601u);  // one at each 1/60 s from 0 to 10 s
  for (std::size_t k = 1; k < times.size(); ++k) {
    const double gap = times[k] - times[k - 1];
    EXPECT_TRUE(std::abs(gap - 0.015) < 1e-9 || std::abs(gap - 0.02) < 1e-9) << k << " " << gap;
    // Never later than the sample time it stands for by a step or more.
    EXPECT_LT(times[k] - double(k) / 60, 0.005) << k;
    EXPECT_GE(times[k] - double(k) / 60, -1e-9) << k;
  }
  std::ifstream in(path);
  std::string line;
  std::size_t lines = 0;
  while (std::getline(in, line))
    ++lines;
  EXPECT_EQ(lines, 602u);  // the header and the rows
}

TEST(TrajectoryRecorder, TheSideFileNamesEveryColumnWithItsUnitAndTheRun) {
  const nlohmann::ordered_json run = {{"scene", "built-in thorax"}, {"heart", "dynamic"}};
  const nlohmann::ordered_json j = trajectory_side_file(run);
  EXPECT_EQ(j["rate_hz"], 60);
  EXPECT_EQ(j["run"]["heart"], "dynamic");
  const std::vector<TrajectoryColumn> columns = trajectory_columns();
  ASSERT_EQ(j["columns"].size(), columns.size());
  for (std::size_t k = 0; k < columns.size(); ++k) {
    EXPECT_EQ(j["columns"][k]["name"], columns[k].name);
    EXPECT_FALSE(j["columns"][k]["meaning"].get<std::string>().empty()) << columns[k].name;
  }
  EXPECT_EQ(j["columns"][1]["unit"], "m");  // forceps_x
}

TEST(TrajectoryRecorder, TheHeaderIsOnDiskAtOnce) {
  const std::string path = ::testing::TempDir() + "imasim_trajectory_header.csv";
  TrajectoryRecorder r{OutputFile(path, "the trajectory file")};
  std::ifstream in(path);
  std::string first;
  std::getline(in, first);
  EXPECT_EQ(first + '\n', trajectory_csv_header());
}

}  // namespace
}  // namespace imasim::metrics
