#pragma once
// Long jobs say what they will cost before they start: `render --frames 100000` at
// 8192x8192 began about two days and terabytes of work without a word, `experiment --trials 1000
// --seconds 3600` two thousand hour-long trials. The estimate is said on stderr; above an hour or
// 10 GB the job waits for --yes. The rates are this project's measurements on the CI's kind of
// machine (2 cores, Mesa llvmpipe; docs/PERFORMANCE.md), so the figures are orders, not promises.
#include <cstdint>
#include <iosfwd>
#include <string>

namespace imasim::cli {

struct JobEstimate {
  double seconds = 0;  // of wall-clock time (unit: s)
  double bytes = 0;    // written (unit: bytes)
};

inline constexpr double kLongJobSeconds = 3600;
inline constexpr double kLargeJobBytes = 10e9;

// Rendering offscreen: 90 ns and 0.5 bytes of PNG a pixel, plus the physics of the simulated
// time, 0.65 s of wall-clock time a simulated second.
JobEstimate render_estimate(std::uint64_t frames, std::uint64_t width, std::uint64_t height,
                            double fps);
// Trials of `seconds` simulated time each, `jobs` at once: 0.85 s a simulated second, 0.4 MB of
// images and 30 kB of recording a simulated second per trial.
JobEstimate study_estimate(std::uint64_t trials, double seconds, int jobs);

// "about 2 h 10 min and 1.9 TB".
std::string describe(const JobEstimate& e);

// Says `what` and its estimate on `err` ("PROGRAM: WHAT: about ..."); false, with how to go on,
// when it is over an hour or 10 GB and `yes` was not given.
bool confirm_job(const std::string& program, const std::string& what, const JobEstimate& e,
                 bool yes, std::ostream& err);

}  // namespace imasim::cli
