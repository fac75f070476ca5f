#include "metrics/plot_ticks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace imasim::metrics {

double nice_step_at_least(double x) {
  if (!(x > 0) || !std::isfinite(x))
    throw std::invalid_argument("nice step of a non-positive size");
  const double decade = std::pow(10.0, std::floor(std::log10(x)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= x * (1 - 1e-9)) return m * decade;
  return 10 * decade;
}

Ticks nice_ticks(double lo, double hi, int target) {
  if (!std::isfinite(lo) || !std::isfinite(hi) || !(lo < hi))
    throw std::invalid_argument("ticks need a finite range lo < hi");
  Ticks t;
  t.step = nice_step_at_least((hi - lo) / double(std::max(target, 2)));
  const double first = std::ceil(lo / t.step - 1e-9) * t.step;
  for (double k = 0;; ++k) {
    const double x = first + k * t.step;
    if (x > hi + 1e-9 * t.step) break;
    t.values.push_back(std::abs(x) < 1e-9 * t.step ? 0.0 : x);
  }
  return t;
}

std::string tick_label(double value, double step) {
  const int decimals = std::clamp(int(-std::floor(std::log10(step) + 1e-9)), 0, 12);
  if (std::abs(value) < 0.5 * std::pow(10.0, -decimals)) value = 0;  // no "-0"
  char text[48];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

}  // namespace imasim::metrics
