#pragma once
// The study's progress bar on stderr: trials done, failed and running, the elapsed time and an
// estimate of the time left. On a terminal one line redrawn in place (at most 5 times a second);
// otherwise (--progress into a file or a pipe) a line at each change of the counts.
#include <chrono>
#include <iosfwd>
#include <string>

#include "trial_processes.hpp"

namespace imasim::cli {

// "[#######.............]  3/6 done  1 failed  2 running  0:42 elapsed  ~1:10 left"
std::string progress_line(const TrialCounts& counts, double elapsed_s, std::size_t bar_width);

class StudyProgress {
 public:
  // `show`: always draw (--progress); else only when `out` is a terminal (stderr's descriptor).
  StudyProgress(bool show, std::ostream& out);
  void update(const TrialCounts& counts);
  // Ends the line on a terminal.
  void finish();

 private:
  using Clock = std::chrono::steady_clock;
  bool show_, terminal_, drawn_ = false;
  std::ostream& out_;
  Clock::time_point start_, last_draw_{};
  TrialCounts last_{};
};

}  // namespace imasim::cli
