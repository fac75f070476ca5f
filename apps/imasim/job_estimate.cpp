#include "job_estimate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <ostream>

namespace imasim::cli {

namespace {

constexpr double kRenderSecondsPerPixel = 90e-9;  // (unit: s)
constexpr double kPngBytesPerPixel = 0.5;
constexpr double kWallPerSimulatedSecond = 0.65;
// With every core running a trial they contend: the harvest study ran 0.85 s a simulated second.
constexpr double kTrialWallPerSimulatedSecond = 0.85;
constexpr double kTrialImageBytes = 0.4e6, kRecordingBytesPerSecond = 30e3;

std::string duration_text(double s) {
  char buffer[64];
  if (s < 60)
    std::snprintf(buffer, sizeof buffer, "%.0f s", std::max(1.0, std::ceil(s)));
  else if (s < 3600)
    std::snprintf(buffer, sizeof buffer, "%.0f min", std::ceil(s / 60));
  else
    std::snprintf(buffer, sizeof buffer, "%.0f h %02.0f min", std::floor(s / 3600),
                  std::floor(std::fmod(s, 3600) / 60));
  return buffer;
}

std::string size_text(double b) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB"};
  int k = 0;
  while (b >= 1000 && k < 5)
    b /= 1000, ++k;
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, k == 0 ? "%.0f %s" : "%.1f %s", b, units[k]);
  return buffer;
}

}  // namespace

JobEstimate render_estimate(std::uint64_t frames, std::uint64_t width, std::uint64_t height,
                            double fps) {
  const double pixels = double(frames) * double(width) * double(height);
  return {pixels * kRenderSecondsPerPixel +
              (fps > 0 ? double(frames) / fps : 0) * kWallPerSimulatedSecond,
          pixels * kPngBytesPerPixel};
}

JobEstimate study_estimate(std::uint64_t trials, double seconds, int jobs) {
  const double rounds = std::ceil(double(trials) / double(std::max(jobs, 1)));
  return {rounds * seconds * kTrialWallPerSimulatedSecond,
          double(trials) * (kTrialImageBytes + seconds * kRecordingBytesPerSecond)};
}

std::string describe(const JobEstimate& e) {
  return "about " + duration_text(e.seconds) + " and " + size_text(e.bytes);
}

bool confirm_job(const std::string& program, const std::string& what, const JobEstimate& e,
                 bool yes, std::ostream& err) {
  err << program << ": " << what << ": " << describe(e) << " of work\n";
  if (yes || (e.seconds <= kLongJobSeconds && e.bytes <= kLargeJobBytes)) return true;
  err << program << ": that is more than an hour or 10 GB; add --yes to start it\n";
  return false;
}

}  // namespace imasim::cli
