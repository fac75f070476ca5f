#pragma once
// Durations in 1 us bins up to a bound, for the haptic loop's period and latency percentiles
// without storing every sample or allocating while the loop runs.
#include <cstdint>
#include <vector>

namespace imasim::haptics {

class DurationHistogram {
 public:
  explicit DurationHistogram(double max_s = 0.05);

  void add(double seconds);
  std::uint64_t count() const { return count_; }
  double mean_s() const { return count_ > 0 ? sum_s_ / double(count_) : 0.0; }
  double max_s() const { return max_s_; }
  // The q-quantile (0 <= q <= 1) to the bin's upper edge (1 us); samples beyond the bound count
  // at the bound. 0 when empty.
  double quantile_s(double q) const;

 private:
  std::vector<std::uint64_t> bins_;  // bins_[k]: durations in [k, k + 1) us
  std::uint64_t count_ = 0;
  double sum_s_ = 0, max_s_ = 0;
};

}  // namespace imasim::haptics
