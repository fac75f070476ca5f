#include "cli_checks.hpp"

#include <charconv>
#include <cmath>
#include <sstream>

#include "math/printable.hpp"
#include "metrics/trainee_name.hpp"

namespace imasim::cli {

namespace {

std::string number_text(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

}  // namespace

CLI::Validator finite_range(double lo, double hi) {
  const std::string interval = "[" + number_text(lo) + ", " + number_text(hi) + "]";
  return CLI::Validator(
      [lo, hi, interval](std::string& text) -> std::string {
        double v = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, v);
        if (ec != std::errc() || ptr != end || !std::isfinite(v))
          return "expected a finite number in " + interval + ", got '" + text + "'";
        if (v < lo || v > hi) return "value " + text + " is outside " + interval;
        return {};
      },
      "FINITE in " + interval);
}

CLI::Validator unsigned_at_most(std::uint64_t max) {
  return CLI::Validator(
      [max](std::string& text) -> std::string {
        std::uint64_t v = 0;
        const char* end = text.data() + text.size();
        const auto [ptr, ec] = std::from_chars(text.data(), end, v);
        if (text.empty() || text.front() == '-' || text.front() == '+' || ec != std::errc() ||
            ptr != end || v > max)
          return "expected a whole number in [0, " + std::to_string(max) + "], got '" + text + "'";
        return {};
      },
      "UINT in [0, " + std::to_string(max) + "]");
}

CLI::Validator non_empty() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        return text.empty() ? std::string("expected a file name, got an empty one") : "";
      },
      "NON-EMPTY");
}

CLI::Validator trainee_name() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        const std::string problem = metrics::trainee_name_problem(text);
        return problem.empty() ? std::string()
                               : "the name '" + printable(text, 80) + "' " + problem;
      },
      "NAME");
}

}  // namespace imasim::cli
