// Points from CSV files (metrics/point_csv.hpp): plain trajectories and centerlines, the
// recorder's per-tool columns, and every malformed file refused naming its line and column.
#include "metrics/point_csv.hpp"

#include <gtest/gtest.h>

#include <string>

namespace imasim::metrics {
namespace {

TEST(PointCsv, PlainTrajectoryWithCrlfBlankLinesAndNoFinalNewline) {
  const PointSeries s = parse_point_csv(
      "t,x,y,z\r\n0,0.001,0.002,0.003\r\n\r\n0.0167, -1e-3 ,0,5e-2", "a.csv", "x", "t");
  ASSERT_EQ(s.points.size(), 2u);
  EXPECT_EQ(s.time[1], 0.0167);
  EXPECT_EQ(s.points[0], Vec3(0.001, 0.002, 0.003));
  EXPECT_EQ(s.points[1], Vec3(-1e-3, 0, 5e-2));
}

TEST(PointCsv, RecorderColumnsPerToolInAnyOrder) {
  const std::string text =
      "t,hook_z,forceps_x,forceps_y,forceps_z,hook_x,hook_y\n"
      "0.0,3,10,20,30,1,2\n"
      "0.5,6,11,21,31,4,5\n";
  const PointSeries hook = parse_point_csv(text, "r.csv", "hook_x", "t");
  ASSERT_EQ(hook.points.size(), 2u);
  EXPECT_EQ(hook.points[1], Vec3(4, 5, 6));
  const PointSeries forceps = parse_point_csv(text, "r.csv", "forceps_x", "t");
  EXPECT_EQ(forceps.points[0], Vec3(10, 20, 30));
}

TEST(PointCsv, CenterlineHasNoTime) {
  const PointSeries c = parse_point_csv("x,y,z\n0,0,0\n0,0,0.1\n", "c.csv", "x", "");
  EXPECT_TRUE(c.time.empty());
  EXPECT_EQ(c.points.size(), 2u);
}

TEST(PointCsv, MalformedFilesNameTheLineAndColumn) {
  struct Case {
    std::string text, message;
  };
  const Case cases[] = {
      {"", "p.csv: empty file: expected a header line"},
      {"t,x,y\n0,1,2\n", "p.csv:1: the header has no column 'z'"},
      {"t,x,y,z\n0,1,2\n", "p.csv:2: expected 4 fields as the header has, got 3"},
      {"t,x,y,z\n\n0,1,two,3\n", "p.csv:3: column 'y': expected a finite number, got 'two'"},
      {"t,x,y,z\n0,1,2,nan\n", "p.csv:2: column 'z': expected a finite number, got 'nan'"},
      {"t,x,y,z\n0,1,2,1e999\n", "p.csv:2: column 'z': expected a finite number"},
      {"t,x,y,z\n1,0,0,0\n0.5,0,0,0\n", "p.csv:3: column 't': time goes backwards"},
      {"t,x,y,z\n0,1,2,3 4\n", "p.csv:2: column 'z': expected a finite number, got '3 4'"},
  };
  for (const Case& c : cases) {
    try {
      parse_point_csv(c.text, "p.csv", "x", "t");
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const PointCsvError& e) {
      EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos)
          << e.what() << "\n  expected: " << c.message;
    }
  }
}

TEST(PointCsv, MissingFileIsNamed) {
  try {
    load_centerline_csv("/nonexistent/centerline.csv");
    ADD_FAILURE();
  } catch (const PointCsvError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/centerline.csv: cannot open"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace imasim::metrics
