#pragma once
// Where a step's time went, stage by stage (unit: s of wall clock). The engine fills the stages
// of its substep loop; the layers above add theirs (the heart and surfaces, contact gathering,
// coupling, instruments, cutting). Timing only reads the clock: results are the same with it.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

namespace imasim::physics {

enum class Stage : std::uint8_t {
  instruments,  // poses, grasping, cautery heating (session)
  cutting,      // fascia and strand cuts, with their topology changes (session)
  heart,        // advancing the heart and its anchors (scene)
  contacts,     // gathering contact candidates, projecting contacts, after-step checks
  predict,      // eq. 1 (engine)
  solve,        // constraint and coupling projection (engine)
  velocities,   // velocity update and damping, eq. 4 (engine)
  coupling,     // XSPH and eq. 9's decay after the solve (tissue)
  surfaces,     // fine meshes, strand ends (tissue)
  count,
};

inline constexpr std::size_t kStageCount = static_cast<std::size_t>(Stage::count);

const char* to_string(Stage stage);

struct StepProfile {
  std::array<double, kStageCount> seconds{};

  double& operator[](Stage s) { return seconds[static_cast<std::size_t>(s)]; }
  double operator[](Stage s) const { return seconds[static_cast<std::size_t>(s)]; }
  StepProfile& operator+=(const StepProfile& other) {
    for (std::size_t k = 0; k < kStageCount; ++k)
      seconds[k] += other.seconds[k];
    return *this;
  }
  double total() const {
    double t = 0;
    for (double s : seconds)
      t += s;
    return t;
  }
};

// Profiles of many steps: per-stage sums and maxima (of each stage separately) and the number
// of steps.
struct ProfileTotals {
  StepProfile sum, max;
  double max_total = 0;
  std::uint64_t steps = 0;

  void add(const StepProfile& p) {
    for (std::size_t k = 0; k < kStageCount; ++k) {
      sum.seconds[k] += p.seconds[k];
      max.seconds[k] = std::max(max.seconds[k], p.seconds[k]);
    }
    max_total = std::max(max_total, p.total());
    ++steps;
  }
  // Mean seconds per step in a stage.
  double mean(Stage s) const { return steps == 0 ? 0.0 : sum[s] / double(steps); }
};

}  // namespace imasim::physics
