#pragma once
// Runs a study's trials as child processes of this same program (posix_spawn of /proc/self/exe),
// at most `jobs` at once: each child's stdout and stderr go to its own files; a child that passes
// the time limit is killed (SIGKILL); a failed or killed child does not stop the others. When
// SIGINT, SIGTERM or SIGHUP reaches this process (interrupt.hpp), no new child starts, the
// running ones get SIGTERM (SIGKILL after a grace period) and the function returns what ended.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace imasim::cli {

struct TrialProcess {
  std::vector<std::string> args;  // after the program's name
  std::string stdout_path, stderr_path;
};

struct TrialExit {
  enum class End { exited, signalled, timed_out, interrupted, not_started, spawn_failed };
  End end = End::not_started;
  int exit_code = -1;  // End::exited
  int signal = 0;      // End::signalled
  double wall_s = 0;   // from start to end (unit: s)
  std::string error;   // End::spawn_failed: why

  bool ok() const { return end == End::exited && exit_code == 0; }
  // "exited with status 3", "killed by signal 9 (Killed)", "timed out after 20 s (killed)", ...
  std::string describe(double timeout_s) const;
};

struct TrialCounts {
  std::size_t total = 0, finished = 0, failed = 0, running = 0;
};

// Wall-clock seconds after SIGTERM before an interrupted child is killed.
inline constexpr double kInterruptGraceSeconds = 10;

// `timeout_s` <= 0: no limit. `on_poll` is called every poll (about 20 times a second) and after
// each change, with the counts so far (failed: any end but exit status 0); `on_finished`, if
// given, as each trial ends, with its index and how (so that what finished is kept should the
// study itself be killed).
std::vector<TrialExit> run_trial_processes(
    const std::vector<TrialProcess>& trials, int jobs, double timeout_s,
    const std::function<void(const TrialCounts&)>& on_poll,
    const std::function<void(std::size_t, const TrialExit&)>& on_finished = {});

}  // namespace imasim::cli
