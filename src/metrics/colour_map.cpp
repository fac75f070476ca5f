#include "metrics/colour_map.hpp"

#include <algorithm>
#include <cmath>

namespace imasim::metrics {

namespace {

// inferno at t = 0, 0.1, ..., 1 (sRGB, 0-255).
constexpr std::array<std::array<double, 3>, 11> kInferno{{{0, 0, 4},
                                                          {22, 11, 57},
                                                          {66, 10, 104},
                                                          {106, 23, 110},
                                                          {147, 38, 103},
                                                          {188, 55, 84},
                                                          {221, 81, 58},
                                                          {243, 120, 25},
                                                          {252, 165, 10},
                                                          {246, 215, 70},
                                                          {252, 255, 164}}};

}  // namespace

std::array<double, 3> heat_colour(double t) {
  t = std::isfinite(t) ? std::clamp(t, 0.0, 1.0) : 0.0;
  const double x = t * double(kInferno.size() - 1);
  const std::size_t k = std::min(std::size_t(x), kInferno.size() - 2);
  const double f = x - double(k);
  std::array<double, 3> rgb{};
  for (std::size_t c = 0; c < 3; ++c)
    rgb[c] = ((1 - f) * kInferno[k][c] + f * kInferno[k + 1][c]) / 255.0;
  return rgb;
}

}  // namespace imasim::metrics
