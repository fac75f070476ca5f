#include "trial_processes.hpp"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstring>
#include <thread>

#include "interrupt.hpp"
#include "spawn_self.hpp"

namespace imasim::cli {

namespace {

using Clock = std::chrono::steady_clock;
constexpr std::chrono::milliseconds kPollInterval{50};

struct Running {
  std::size_t index = 0;
  pid_t pid = -1;
  Clock::time_point start;
  bool killed_for_time = false, terminated = false;
  Clock::time_point terminated_at;
};

double seconds_since(Clock::time_point t) {
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// Starts /proc/self/exe with `trial`'s arguments; -1 and `error` set when it cannot.
pid_t spawn_trial(const TrialProcess& trial, std::string& error) {
  int e = 0;
  const pid_t pid = spawn_self(trial.args, trial.stdout_path, trial.stderr_path, e);
  if (pid < 0) {
    error = "cannot start the trial (" + trial.stdout_path + ", " + trial.stderr_path +
            "): " + std::strerror(e);
  }
  return pid;
}

}  // namespace

std::string TrialExit::describe(double timeout_s) const {
  switch (end) {
    case End::exited:
      return exit_code == 0 ? "ok" : "exited with status " + std::to_string(exit_code);
    case End::signalled: {
      const char* name = strsignal(signal);
      return "killed by signal " + std::to_string(signal) +
             (name ? " (" + std::string(name) + ")" : "");
    }
    case End::timed_out:
      return "timed out after " + std::to_string(std::lround(timeout_s)) +
             " s of wall-clock time (killed)";
    case End::interrupted:
      return "interrupted (the study was stopped)";
    case End::not_started:
      return "not run (the study was stopped first)";
    case End::spawn_failed:
      return error;
  }
  return "unknown";
}

std::vector<TrialExit> run_trial_processes(
    const std::vector<TrialProcess>& trials, int jobs, double timeout_s,
    const std::function<void(const TrialCounts&)>& on_poll,
    const std::function<void(std::size_t, const TrialExit&)>& on_finished) {
  std::vector<TrialExit> exits(trials.size());
  std::vector<Running> running;
  std::size_t next = 0;
  TrialCounts counts;
  counts.total = trials.size();
  auto finish = [&](std::size_t index, TrialExit e) {
    if (!e.ok()) ++counts.failed;
    ++counts.finished;
    exits[index] = std::move(e);
    if (on_finished) on_finished(index, exits[index]);
  };
  while (next < trials.size() || !running.empty()) {
    const bool stopping = interrupt_signal() != 0;
    while (!stopping && next < trials.size() && running.size() < std::size_t(std::max(jobs, 1))) {
      Running r;
      r.index = next++;
      r.start = Clock::now();
      std::string error;
      r.pid = spawn_trial(trials[r.index], error);
      if (r.pid < 0) {
        TrialExit e;
        e.end = TrialExit::End::spawn_failed;
        e.error = error;
        finish(r.index, e);
        continue;
      }
      running.push_back(r);
    }
    for (auto it = running.begin(); it != running.end();) {
      int status = 0;
      const pid_t done = ::waitpid(it->pid, &status, WNOHANG);
      if (done == it->pid) {
        TrialExit e;
        e.wall_s = seconds_since(it->start);
        // A trial that finished its work as it was told to stop still counts as done.
        if (WIFEXITED(status) && WEXITSTATUS(status) == 0) {
          e.end = TrialExit::End::exited;
          e.exit_code = 0;
        } else if (it->killed_for_time) {
          e.end = TrialExit::End::timed_out;
        } else if (it->terminated) {
          e.end = TrialExit::End::interrupted;
        } else if (WIFEXITED(status)) {
          e.end = TrialExit::End::exited;
          e.exit_code = WEXITSTATUS(status);
        } else {
          e.end = TrialExit::End::signalled;
          e.signal = WTERMSIG(status);
        }
        finish(it->index, e);
        it = running.erase(it);
        continue;
      }
      if (timeout_s > 0 && !it->killed_for_time && seconds_since(it->start) > timeout_s) {
        ::kill(it->pid, SIGKILL);
        it->killed_for_time = true;
      }
      if (stopping && !it->terminated) {
        ::kill(it->pid, SIGTERM);
        it->terminated = true;
        it->terminated_at = Clock::now();
      } else if (it->terminated && seconds_since(it->terminated_at) > kInterruptGraceSeconds) {
        ::kill(it->pid, SIGKILL);
      }
      ++it;
    }
    if (stopping && next < trials.size()) {
      // Never started: each is reported as not run.
      for (; next < trials.size(); ++next)
        finish(next, TrialExit{});
    }
    counts.running = running.size();
    on_poll(counts);
    if (!running.empty()) std::this_thread::sleep_for(kPollInterval);
  }
  return exits;
}

}  // namespace imasim::cli
