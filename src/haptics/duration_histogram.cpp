#include "haptics/duration_histogram.hpp"

#include <algorithm>
#include <cmath>

namespace imasim::haptics {

DurationHistogram::DurationHistogram(double max_s)
    : bins_(std::size_t(std::max(1.0, std::ceil(max_s * 1e6))) + 1, 0) {}

void DurationHistogram::add(double seconds) {
  if (!(seconds >= 0)) seconds = 0;
  const double us = seconds * 1e6;
  const std::size_t bin = us >= double(bins_.size() - 1) ? bins_.size() - 1 : std::size_t(us);
  ++bins_[bin];
  ++count_;
  sum_s_ += seconds;
  max_s_ = std::max(max_s_, seconds);
}

double DurationHistogram::quantile_s(double q) const {
  if (count_ == 0) return 0;
  const auto rank = std::uint64_t(std::ceil(std::clamp(q, 0.0, 1.0) * double(count_)));
  std::uint64_t seen = 0;
  for (std::size_t k = 0; k < bins_.size(); ++k) {
    seen += bins_[k];
    if (seen >= std::max<std::uint64_t>(rank, 1)) return double(k + 1) * 1e-6;
  }
  return double(bins_.size()) * 1e-6;
}

}  // namespace imasim::haptics
