#pragma once
// Axis ticks at "nice" values (1, 2 or 5 times a power of ten), as plots and colour bars label
// their axes, and their labels with as many decimals as the step needs.
#include <string>
#include <vector>

namespace imasim::metrics {

struct Ticks {
  std::vector<double> values;  // ascending, inside [lo, hi]
  double step = 0;
};

// About `target` ticks (at least 2) covering [lo, hi]; lo < hi, both finite.
Ticks nice_ticks(double lo, double hi, int target);

// The smallest nice value (1, 2 or 5 times a power of ten) at or above `x` > 0.
double nice_step_at_least(double x);

// `value` with the decimals a tick step of `step` needs ("0.25", "10"); "0" for a value that is
// zero up to rounding.
std::string tick_label(double value, double step);

}  // namespace imasim::metrics
