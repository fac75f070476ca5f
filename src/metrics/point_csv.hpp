#pragma once
// Points from CSV files for the scores (SPEC S6): a tool trajectory, either a plain file with
// the header `t,x,y,z` or the recorder's file with columns `t_s,<tool>_x,<tool>_y,<tool>_z`; an IMA
// centerline with the header `x,y,z`. Metres, comma-separated, one row a point; blank lines and
// a final newline are fine, CRLF too. Errors name the file, the line and the column.
#include <stdexcept>
#include <string>
#include <vector>

#include "math/types.hpp"

namespace imasim::metrics {

class PointCsvError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline constexpr std::uint64_t kMaxPointCsvBytes = std::uint64_t(512) << 20;  // 512 MiB

struct PointSeries {
  std::vector<double> time;  // empty for a centerline (unit: s)
  std::vector<Vec3> points;  // (unit: m)
};

// `x_column`: the name of the x column ("x", or "<tool>_x" for the recorder's file); y and z
// are found by the same prefix. `time_column`: "t", or empty when the file has none. `path`
// names the file in messages.
PointSeries parse_point_csv(const std::string& text, const std::string& path,
                            const std::string& x_column, const std::string& time_column);
PointSeries load_point_csv(const std::string& path, const std::string& x_column,
                           const std::string& time_column);

// A trajectory: the plain `t,x,y,z` file when `tool` is empty, else the recorder's columns of
// that tool. A time that goes backwards is an error.
PointSeries load_trajectory_csv(const std::string& path, const std::string& tool);
PointSeries load_centerline_csv(const std::string& path);

}  // namespace imasim::metrics
