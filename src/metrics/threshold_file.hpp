#pragma once
// Proficiency thresholds from a file: a JSON object of metric name to threshold,
//   {"time_to_complete_s": 300, "heart_contacts": 1}
// replacing the defaults of metrics/trainee_metrics.hpp for those metrics. Errors name the file
// and the line: a file that is not JSON, not an object, a name that is no metric (with the
// nearest one), a value that is not a finite number.
#include <map>
#include <stdexcept>
#include <string>

namespace imasim::metrics {

class ThresholdFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

inline constexpr std::uint64_t kMaxThresholdFileBytes = 1 << 20;

std::map<std::string, double> parse_threshold_file(const std::string& text,
                                                   const std::string& path);
std::map<std::string, double> load_threshold_file(const std::string& path);

}  // namespace imasim::metrics
