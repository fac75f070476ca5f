#pragma once
// Runs the solver's data-parallel loops on a fixed number of threads (a WorkerTeam: the caller
// and threads - 1 workers). Work is split into fixed chunks whose results do not depend on which
// thread runs them, so a step gives bit-for-bit the same state for any thread count.
#include <algorithm>
#include <cstddef>
#include <cstdint>
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
  void run_side_by_side(const A& a, const B& b) const {
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
    for_chunks_in_parts(n, chunk,
                        [&](std::size_t, std::size_t begin, std::size_t end) { body(begin, end); });
  }

  // Keeps the team's workers spinning while it lives (WorkerTeam::keep_awake): for a step whose
  // parallel loops are parted by serial stretches of more than 50 us. Not nested.
  class Awake {
   public:
    explicit Awake(const Executor& exec) : team_(exec.team_.get()) {
      if (team_) team_->keep_awake(true);
    }
    ~Awake() {
      if (team_) team_->keep_awake(false);
    }
    Awake(const Awake&) = delete;
    Awake& operator=(const Awake&) = delete;

   private:
    WorkerTeam* team_;
  };

  // How many times the team's workers have gone to sleep (WorkerTeam::sleeps).
  std::uint64_t worker_sleeps() const { return team_ ? team_->sleeps() : 0; }

  // How many parts for_chunks_in_parts splits its work into (scratch to keep per part).
  std::size_t parts() const { return team_ ? team_->parts() : 1; }

  // for_chunks, telling body(part, begin, end) which part runs the chunk, in [0, parts()): each
  // part may keep its own scratch. A part runs on one thread at a time, its chunks in order.
  template <class Body>
  void for_chunks_in_parts(std::size_t n, std::size_t chunk, const Body& body) const {
    const std::size_t chunks = (n + chunk - 1) / chunk;
    auto run_chunks = [&](std::size_t part, std::size_t c0, std::size_t c1) {
      for (std::size_t c = c0; c < c1; ++c)
        body(part, c * chunk, std::min(n, (c + 1) * chunk));
    };
    if (!team_ || chunks < 2) {
      run_chunks(0, 0, chunks);
      return;
    }
    const std::size_t parts = team_->parts();
    team_->run([&](unsigned p) { run_chunks(p, chunks * p / parts, chunks * (p + 1) / parts); });
  }

 private:
  int threads_ = 1;
  std::unique_ptr<WorkerTeam> team_;  // null for one thread: no other thread at all
};

}  // namespace imasim::physics
