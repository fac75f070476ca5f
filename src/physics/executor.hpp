#pragma once
// Runs the solver's data-parallel loops on a fixed number of threads (a WorkerTeam: the caller
// and threads - 1 workers). Work is split into fixed chunks whose results do not depend on which
// thread runs them, so a step gives bit-for-bit the same state for any thread count.
#include <algorithm>
#include <cstddef>
#include <memory>

#include "physics/worker_team.hpp"

namespace imasim::physics {

class Executor {
 public:
  // threads <= 0: all hardware threads.
  explicit Executor(int threads = 1);

  int threads() const { return threads_; }

  // Runs f; kept so that callers mark the region their parallel loops belong to.
  template <class F>
  void run(F&& f) {
    f();
  }

  // Calls a() and b() at once, on two threads when there are (a on the caller's), and returns
  // when both have. They must touch disjoint data and not throw; loops they call run serially.
  template <class A, class B>
  void run_side_by_side(const A& a, const B& b) {
    if (!team_) {
      a();
      b();
      return;
    }
    team_->run([&](unsigned p) {
      if (p == 0) a();
      if (p == 1) b();
    });
  }

  // Calls body(begin, end) over the fixed chunks [c * chunk, min(n, (c + 1) * chunk)) that
  // cover [0, n), in parallel: each thread of the team takes a fixed, contiguous run of chunks.
  // The chunk boundaries do not depend on the thread count, so every index is processed by the
  // same code path (vectorised body or scalar tail, with the same floating-point contraction)
  // whatever the number of threads: results are bit-identical. body must not throw.
  template <class Body>
  void for_chunks(std::size_t n, std::size_t chunk, const Body& body) const {
    const std::size_t chunks = (n + chunk - 1) / chunk;
    auto run_chunks = [&](std::size_t c0, std::size_t c1) {
      for (std::size_t c = c0; c < c1; ++c)
        body(c * chunk, std::min(n, (c + 1) * chunk));
    };
    if (!team_ || chunks < 2) {
      run_chunks(0, chunks);
      return;
    }
    const std::size_t parts = team_->parts();
    team_->run([&](unsigned p) { run_chunks(chunks * p / parts, chunks * (p + 1) / parts); });
  }

 private:
  int threads_ = 1;
  std::unique_ptr<WorkerTeam> team_;  // null for one thread: no other thread at all
};

}  // namespace imasim::physics
