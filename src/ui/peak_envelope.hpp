#pragma once
// A history thinned for plotting: each value the largest of `group` consecutive samples, so a
// short peak stays on the plot. The force plots draw 60 points a channel instead of 240: each
// segment is two triangles for the software rasteriser, and the six plots were half the panels'
// triangles (docs/PERFORMANCE.md).
#include <algorithm>
#include <array>
#include <cstddef>

namespace imasim::ui {

template <std::size_t group, std::size_t count>
std::array<float, count / group> peak_envelope(const std::array<float, count>& history) {
  static_assert(group > 0 && count % group == 0);
  std::array<float, count / group> peaks{};
  for (std::size_t i = 0; i < peaks.size(); ++i)
    peaks[i] = *std::max_element(history.begin() + std::ptrdiff_t(group * i),
                                 history.begin() + std::ptrdiff_t(group * (i + 1)));
  return peaks;
}

}  // namespace imasim::ui
