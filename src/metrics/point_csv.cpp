#include "metrics/point_csv.hpp"

#include <charconv>
#include <cmath>
#include <string_view>

#include "math/printable.hpp"
#include "math/text_file.hpp"

namespace imasim::metrics {

namespace {

std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = line.find(',', start);
    std::string_view f =
        line.substr(start, comma == std::string_view::npos ? line.npos : comma - start);
    while (!f.empty() && (f.front() == ' ' || f.front() == '\t'))
      f.remove_prefix(1);
    while (!f.empty() && (f.back() == ' ' || f.back() == '\t'))
      f.remove_suffix(1);
    out.push_back(f);
    if (comma == std::string_view::npos) return out;
    start = comma + 1;
  }
}

[[noreturn]] void fail(const std::string& path, std::size_t line, const std::string& message) {
  throw PointCsvError(path + ":" + std::to_string(line) + ": " + message);
}

}  // namespace

PointSeries parse_point_csv(const std::string& text, const std::string& path,
                            const std::string& x_column, const std::string& time_column) {
  const std::string prefix =
      x_column.substr(0, x_column.size() - 1);  // "x" -> "", "hook_x" -> "hook_"
  const std::string wanted[4] = {time_column, x_column, prefix + "y", prefix + "z"};
  int column[4] = {-1, -1, -1, -1};
  PointSeries out;
  std::size_t line_no = 0, header_line = 0;
  std::size_t header_fields = 0;
  std::string_view rest = text;
  while (!rest.empty()) {
    const std::size_t end = rest.find('\n');
    std::string_view line = rest.substr(0, end);
    rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (line.find_first_not_of(" \t") == std::string_view::npos) continue;
    const std::vector<std::string_view> fields = split_fields(line);
    if (header_line == 0) {
      header_line = line_no;
      header_fields = fields.size();
      for (const int k : {1, 2, 3, 0}) {  // a tool's columns first: the likelier mistake
        if (wanted[k].empty()) continue;
        for (std::size_t f = 0; f < fields.size(); ++f)
          if (fields[f] == wanted[k]) column[k] = int(f);
        if (column[k] < 0)
          fail(path, line_no,
               "the header has no column '" + wanted[k] + "' (got " + printable(line, 120) + ")");
      }
      continue;
    }
    if (fields.size() != header_fields)
      fail(path, line_no,
           "expected " + std::to_string(header_fields) + " fields as the header has, got " +
               std::to_string(fields.size()));
    double v[4] = {0, 0, 0, 0};
    for (int k = 0; k < 4; ++k) {
      if (column[k] < 0) continue;
      const std::string_view f = fields[std::size_t(column[k])];
      const auto [ptr, ec] = std::from_chars(f.data(), f.data() + f.size(), v[k]);
      if (ec != std::errc() || ptr != f.data() + f.size() || !std::isfinite(v[k]))
        fail(
            path, line_no,
            "column '" + wanted[k] + "': expected a finite number, got '" + printable(f, 40) + "'");
    }
    if (column[0] >= 0) {
      if (!out.time.empty() && v[0] < out.time.back())
        fail(path, line_no, "column '" + wanted[0] + "': time goes backwards");
      out.time.push_back(v[0]);
    }
    out.points.emplace_back(Real(v[1]), Real(v[2]), Real(v[3]));
  }
  if (header_line == 0) throw PointCsvError(path + ": empty file: expected a header line");
  return out;
}

PointSeries load_point_csv(const std::string& path, const std::string& x_column,
                           const std::string& time_column) {
  const TextFile file = read_text_file(path, kMaxPointCsvBytes, "CSV file");
  if (!file.error.empty()) throw PointCsvError(path + ": " + file.error);
  return parse_point_csv(file.text, path, x_column, time_column);
}

PointSeries load_trajectory_csv(const std::string& path, const std::string& tool) {
  // The recorder names its time column by its unit, as its other columns are named.
  return tool.empty() ? load_point_csv(path, "x", "t") : load_point_csv(path, tool + "_x", "t_s");
}

PointSeries load_centerline_csv(const std::string& path) {
  return load_point_csv(path, "x", "");
}

}  // namespace imasim::metrics
