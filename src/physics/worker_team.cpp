#include "physics/worker_team.hpp"

#include <chrono>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace imasim::physics {

namespace {

// A hint to the core that this is a spin-wait (frees its pipeline for a sibling hyperthread).
inline void relax() {
#if defined(__x86_64__) || defined(__i386__)
  _mm_pause();
#endif
}

// How long a worker spins for the next job before it sleeps: longer than the gaps between a
// step's loops, shorter than a paced session's wait between steps.
constexpr auto kSpinBeforeSleep = std::chrono::microseconds(50);

}  // namespace

WorkerTeam::WorkerTeam(unsigned threads)
    : parts_(threads < 1 ? 1 : threads),
      claimed_(std::make_unique<std::atomic<std::uint32_t>[]>(parts_)),
      finished_(std::make_unique<std::atomic<std::uint32_t>[]>(parts_)) {
  for (unsigned p = 0; p < parts_; ++p) {
    claimed_[p].store(1);  // no job yet
    finished_[p].store(1);
  }
  workers_.reserve(parts_ - 1);
  for (unsigned p = 1; p < parts_; ++p)
    workers_.emplace_back([this, p] { work(p); });
}

WorkerTeam::~WorkerTeam() {
  stop_.store(true, std::memory_order_relaxed);
  epoch_.fetch_add(1, std::memory_order_release);
  epoch_.notify_all();
  for (std::thread& t : workers_)
    t.join();
}

void WorkerTeam::keep_awake(bool awake) {
  awake_.store(awake, std::memory_order_relaxed);
  if (!awake) return;
  epoch_.fetch_add(1, std::memory_order_release);  // no job: a woken worker finds none to claim
  epoch_.notify_all();
}

void WorkerTeam::dispatch(const void* job, Call call) {
  job_ = job;
  call_ = call;
  for (unsigned p = 1; p < parts_; ++p) {
    finished_[p].store(0, std::memory_order_relaxed);
    claimed_[p].store(0, std::memory_order_release);  // publishes job_ and call_ to its claimer
  }
  epoch_.fetch_add(1, std::memory_order_release);
  epoch_.notify_all();  // no system call while every worker spins
}

void WorkerTeam::finish(const void* job, Call call) {
  for (unsigned p = 1; p < parts_; ++p) {
    if (claimed_[p].exchange(1, std::memory_order_acq_rel) != 0) continue;
    call(job, p);
    finished_[p].store(1, std::memory_order_relaxed);
  }
  for (unsigned p = 1; p < parts_; ++p)
    for (unsigned spin = 1; finished_[p].load(std::memory_order_acquire) == 0; ++spin) {
      relax();
      if (spin % 64 == 0) std::this_thread::yield();  // a worker preempted mid-part
    }
  busy_.store(false, std::memory_order_release);
}

void WorkerTeam::work(unsigned part) {
  std::uint32_t seen = 0;
  for (;;) {
    std::uint32_t epoch = epoch_.load(std::memory_order_acquire);
    if (epoch == seen) {
      const auto give_up = std::chrono::steady_clock::now() + kSpinBeforeSleep;
      for (unsigned spin = 1; epoch == seen; ++spin) {
        relax();
        // The clock is read now and then only: it costs more than a pause.
        if (spin % 256 == 0 && !awake_.load(std::memory_order_relaxed) &&
            std::chrono::steady_clock::now() > give_up) {
          sleeps_.fetch_add(1, std::memory_order_relaxed);
          epoch_.wait(seen, std::memory_order_acquire);
        }
        epoch = epoch_.load(std::memory_order_acquire);
      }
    }
    seen = epoch;
    if (stop_.load(std::memory_order_relaxed)) return;
    // A worker woken late may find its part done by the caller, or claim the next job's.
    if (claimed_[part].exchange(1, std::memory_order_acq_rel) != 0) continue;
    call_(job_, part);
    finished_[part].store(1, std::memory_order_release);
  }
}

}  // namespace imasim::physics
