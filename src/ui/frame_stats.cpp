#include "ui/frame_stats.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace imasim::ui {

FrameStats frame_stats(std::vector<double> p) {
  std::erase_if(p, [](double v) { return !(v > 0) || !std::isfinite(v); });
  FrameStats s;
  if (p.empty()) return s;
  std::sort(p.begin(), p.end());
  auto rank = [&](double q) {
    const auto k = static_cast<std::size_t>(std::ceil(q * double(p.size())));
    return p[std::clamp<std::size_t>(k, 1, p.size()) - 1];
  };
  s.median_fps = 1 / rank(0.5);
  s.p99_frame_ms = 1000 * rank(0.99);
  s.mean_fps = double(p.size()) / std::accumulate(p.begin(), p.end(), 0.0);
  return s;
}

}  // namespace imasim::ui
