#pragma once
// Runs the solver's data-parallel loops on a fixed number of threads (a oneTBB task arena).
// Work is split into disjoint index ranges whose results do not depend on how they are
// scheduled, so a step gives bit-for-bit the same state for any thread count.
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

  // Calls body(begin, end) over disjoint ranges covering [0, n). Ranges below 2 * grain run
  // inline on the calling thread. Call from inside run().
  template <class Body>
  void for_ranges(std::size_t n, std::size_t grain, const Body& body) const {
    if (!arena_ || n < 2 * grain) {
      if (n > 0) body(std::size_t(0), n);
      return;
    }
    tbb::parallel_for(
        tbb::blocked_range<std::size_t>(0, n, grain),
        [&body](const tbb::blocked_range<std::size_t>& r) { body(r.begin(), r.end()); },
        tbb::static_partitioner());
  }

 private:
  int threads_ = 1;
  std::unique_ptr<tbb::task_arena> arena_;  // null for one thread: no scheduler at all
};

}  // namespace imasim::physics
