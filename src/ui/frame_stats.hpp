#pragma once
// Frame-rate figures from the times between consecutive frames (unit: s): the median frame rate
// and the 99th percentile of the frame time (the window's benchmark).
#include <vector>

namespace imasim::ui {

struct FrameStats {
  double median_fps = 0, mean_fps = 0, p99_frame_ms = 0;
};

// Nearest-rank percentiles; zeros for no periods. Non-positive periods are left out.
FrameStats frame_stats(std::vector<double> periods_s);

}  // namespace imasim::ui
