// libFuzzer target: point CSV files (metrics/point_csv.hpp), the trajectories and centerlines
// the scoring tools read. Any bytes are either refused with PointCsvError or give finite points
// with times that never go backwards; written back as a plain `t,x,y,z` file
// (17 significant digits) they read back to the same points.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

#include "fuzz_check.hpp"
#include "metrics/point_csv.hpp"

namespace {

std::string exact(double v) {
  char text[64];
  std::snprintf(text, sizeof text, "%.17g", v);  // round-trips a double exactly
  return text;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace imasim;
  const std::string text(reinterpret_cast<const char*>(data), size);
  metrics::PointSeries s;
  try {
    // The recorder's columns when the header names a tool "a", else the plain ones.
    const bool tool = text.find("a_x") != std::string::npos;
    s = metrics::parse_point_csv(text, "fuzz.csv", tool ? "a_x" : "x", "t");
  } catch (const metrics::PointCsvError&) {
    return 0;
  }
  fuzz::require(s.time.size() == s.points.size(), "a point without its time");
  std::string written = "t,x,y,z\n";
  for (std::size_t k = 0; k < s.points.size(); ++k) {
    fuzz::require(s.points[k].allFinite() && std::isfinite(s.time[k]),
                  "an accepted value is not finite");
    fuzz::require(k == 0 || s.time[k] >= s.time[k - 1], "an accepted time goes backwards");
    written += exact(s.time[k]) + "," + exact(s.points[k].x()) + "," + exact(s.points[k].y()) +
               "," + exact(s.points[k].z()) + "\n";
  }
  const metrics::PointSeries again = metrics::parse_point_csv(written, "again.csv", "x", "t");
  fuzz::require(again.points == s.points && again.time == s.time,
                "points written back do not read back the same");
  return 0;
}
