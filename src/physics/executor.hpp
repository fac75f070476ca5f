#pragma once
// Runs the solver's data-parallel loops on a fixed number of threads (a oneTBB task arena).
// Work is split into disjoint index ranges whose results do not depend on how they are
// scheduled, so a step gives bit-for-bit the same state for any thread count.
#include <algorithm>
#include <cstddef>
#include <memory>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

namespace imasim::physics {

class Executor {
 public:
  // threads <= 0: all hardware threads.
  explicit Executor(int threads = 1);

  int threads() const { return threads_; }

  // Runs f inside this executor's arena; parallel loops called from f use its threads.
  template <class F>
  void run(F&& f) {
    if (arena_) {
      arena_->execute(f);
    } else {
      f();
    }
  }

  // Calls body(begin, end) over the fixed chunks [c * chunk, min(n, (c + 1) * chunk)) that
  // cover [0, n), in parallel. The chunk boundaries do not depend on the thread count, so every
  // index is processed by the same code path (vectorised body or scalar tail, with the same
  // floating-point contraction) whatever the number of threads: results are bit-identical.
  // Call from inside run().
  template <class Body>
  void for_chunks(std::size_t n, std::size_t chunk, const Body& body) const {
    const std::size_t chunks = (n + chunk - 1) / chunk;
    auto run_chunks = [&](std::size_t c0, std::size_t c1) {
      for (std::size_t c = c0; c < c1; ++c)
        body(c * chunk, std::min(n, (c + 1) * chunk));
    };
    if (!arena_ || chunks < 2) {
      run_chunks(0, chunks);
      return;
    }
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, chunks),
        [&](const tbb::blocked_range<std::size_t>& r) { run_chunks(r.begin(), r.end()); },
        tbb::static_partitioner());
  }

 private:
  int threads_ = 1;
  std::unique_ptr<tbb::task_arena> arena_;  // null for one thread: no scheduler at all
};

}  // namespace imasim::physics
