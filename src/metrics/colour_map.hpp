#pragma once
// The heat maps' colour map: perceptually uniform from dark purple through red and orange to pale
// yellow (matplotlib's "inferno", interpolated between eleven of its colours), so equal steps of
// density look like equal steps of colour and the map reads in grey too.
#include <array>

namespace imasim::metrics {

// The colour at t in [0, 1] (clamped), each channel in [0, 1]; t = 1 is the hot end.
std::array<double, 3> heat_colour(double t);

}  // namespace imasim::metrics
