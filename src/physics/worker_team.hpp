#pragma once
// A fixed team of threads for the step's short parallel work: the caller and threads - 1
// workers, each taking its own part of every job. Why not a task scheduler: handing a job to a
// oneTBB arena cost about 3 us (two threads took the example session from 2.6 to 5.3 ms a step
// when its colours were split), while here a worker spins on a counter between jobs, so a hand-over
// costs a cache line's round trip (0.8 us on this machine). A worker that has waited about 50 us
// sleeps (a futex: std::atomic::wait), so a paced session leaves the cores to the haptic loop and
// the renderer between steps. A step with serial stretches longer than that between its loops
// keeps the team awake for its length (keep_awake): waking a sleeping worker takes longer than
// many of those loops, which the caller would then run alone.
//
// A part no worker has started when the caller is done with its own is run by the caller: a
// worker the system has not scheduled (more threads than free cores) delays nothing. Parts are
// fixed by the caller (part p of parts()), so whichever thread runs a part computes the same.
#include <atomic>
#include <cstdint>
#include <memory>
#include <thread>
#include <vector>

namespace imasim::physics {

class WorkerTeam {
 public:
  // threads >= 1: the caller and threads - 1 workers started here.
  explicit WorkerTeam(unsigned threads);
  ~WorkerTeam();
  WorkerTeam(const WorkerTeam&) = delete;
  WorkerTeam& operator=(const WorkerTeam&) = delete;

  unsigned parts() const { return parts_; }
  // While kept awake, a worker spins between jobs however long the gap (a step's serial stretches
  // between its parallel loops), and one asleep is woken now, ahead of the next job; then it goes
  // back to sleeping after about 50 us (a paced session's wait between steps).
  void keep_awake(bool awake);
  // How many times a worker has gone to sleep (for tests and diagnostics).
  std::uint64_t sleeps() const { return sleeps_.load(std::memory_order_relaxed); }

  // Calls part(p) once for every p in [0, parts()), p = 0 on the calling thread, and returns when
  // all have returned. part must not throw. One job at a time: a call from inside a part (or from
  // another thread while a job runs) runs every part on the calling thread instead.
  template <class Part>
  void run(const Part& part) {
    if (parts_ == 1 || busy_.exchange(true, std::memory_order_acquire)) {
      for (unsigned p = 0; p < parts_; ++p)
        part(p);
      return;
    }
    const auto call = [](const void* f, unsigned p) { (*static_cast<const Part*>(f))(p); };
    dispatch(&part, call);
    part(0);
    finish(&part, call);
  }

 private:
  using Call = void (*)(const void*, unsigned);
  void dispatch(const void* job, Call call);
  // Runs the parts no worker has claimed, then waits for those that were.
  void finish(const void* job, Call call);
  void work(unsigned part);

  unsigned parts_ = 1;
  const void* job_ = nullptr;
  Call call_ = nullptr;
  std::atomic<bool> stop_{false};
  std::atomic<bool> busy_{false};
  std::atomic<bool> awake_{false};
  std::atomic<std::uint64_t> sleeps_{0};
  alignas(64) std::atomic<std::uint32_t> epoch_{0};  // bumped to hand over a job
  // Per part: taken by a thread (the worker or the caller), and finished.
  std::unique_ptr<std::atomic<std::uint32_t>[]> claimed_, finished_;
  std::vector<std::thread> workers_;
};

}  // namespace imasim::physics
