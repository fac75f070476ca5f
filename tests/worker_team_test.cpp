// The solver's thread team (physics/worker_team.hpp) and the executor over it: every part of a
// job runs exactly once and the job returns only when all have; a part no worker has started is
// run by the caller, so a worker that never gets a core delays nothing; a job started from inside
// a part runs inline; many jobs in a row hand over cleanly.
#include <gtest/gtest.h>

#include <array>
#include <atomic>
#include <chrono>
#include <set>
#include <thread>
#include <vector>

#include "physics/executor.hpp"
#include "physics/worker_team.hpp"

namespace imasim::physics {
namespace {

TEST(WorkerTeam, EveryPartRunsOnceAndTheJobWaitsForAll) {
  WorkerTeam team(3);
  ASSERT_EQ(team.parts(), 3u);
  for (int job = 0; job < 2000; ++job) {
    std::array<std::atomic<int>, 3> runs{};
    team.run([&](unsigned p) {
      if (job % 100 == 0) std::this_thread::sleep_for(std::chrono::microseconds(200));
      runs[p].fetch_add(1, std::memory_order_relaxed);
    });
    for (unsigned p = 0; p < 3; ++p)
      ASSERT_EQ(runs[p].load(), 1) << "job " << job << ", part " << p;
  }
}

TEST(WorkerTeam, TheCallerRunsPartZeroAndAWorkerTheOthersWhenItIsFree) {
  WorkerTeam team(2);
  std::set<std::thread::id> seen;
  int on_worker = 0;
  for (int job = 0; job < 200; ++job) {
    std::thread::id ids[2];
    std::atomic<bool> claimed{false};
    // Part 0 waits until part 1 has started, or 50 ms: on a loaded machine (the tests run two
    // at a time) the worker may wait a time slice or more for a core, and a fixed short wait
    // would leave its part to the caller.
    team.run([&](unsigned p) {
      if (p == 0) {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(50);
        while (!claimed.load() && std::chrono::steady_clock::now() < deadline)
          std::this_thread::sleep_for(std::chrono::microseconds(50));
      } else {
        claimed.store(true);
      }
      ids[p] = std::this_thread::get_id();
    });
    EXPECT_EQ(ids[0], std::this_thread::get_id());
    on_worker += ids[1] != std::this_thread::get_id();
  }
  // A worker that is not scheduled in time leaves its part to the caller; most jobs are split.
  EXPECT_GT(on_worker, 100);
}

TEST(WorkerTeam, APartNoWorkerStartedIsRunByTheCaller) {
  WorkerTeam team(2);
  // Between these jobs the worker has gone to sleep (it spins about 50 us); waking it takes
  // longer than the caller's empty part 0, so the caller takes part 1 itself rather than wait.
  int by_caller = 0;
  for (int job = 0; job < 50; ++job) {
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
    std::thread::id runner;
    std::atomic<int> runs{0};
    team.run([&](unsigned p) {
      runs.fetch_add(1);
      if (p == 1) runner = std::this_thread::get_id();
    });
    ASSERT_EQ(runs.load(), 2);
    by_caller += runner == std::this_thread::get_id();
  }
  EXPECT_GT(by_caller, 0);
  // The worker, woken late, finds its part taken and leaves the next jobs whole.
  for (int job = 0; job < 1000; ++job) {
    std::atomic<int> runs{0};
    team.run([&](unsigned) { runs.fetch_add(1); });
    ASSERT_EQ(runs.load(), 2);
  }
}

// Kept awake (a step whose loops are parted by serial stretches), a worker does not sleep through
// gaps far longer than its spin; let go, it sleeps again. (Its sleeps are counted, not timed: a
// worker the machine does not schedule cannot sleep either, so the first half holds however
// loaded the machine is, and the second waits as long as it takes.)
// True once the worker, not the caller, ran part 1 of a job (the caller waits up to 50 ms for it).
bool worker_ran_a_part(WorkerTeam& team) {
  std::atomic<bool> started{false};
  std::thread::id runner;
  team.run([&](unsigned p) {
    if (p == 1) {
      started.store(true);
      runner = std::this_thread::get_id();
      return;
    }
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(50);
    while (!started.load() && std::chrono::steady_clock::now() < deadline)
      std::this_thread::sleep_for(std::chrono::microseconds(50));
  });
  return runner != std::this_thread::get_id();
}

TEST(WorkerTeam, AWorkerKeptAwakeSpinsThroughLongGapsAndSleepsOnceLetGo) {
  WorkerTeam team(2);
  team.keep_awake(true);
  // Once the worker has run a job handed over after keep_awake, it has seen it: no sleep it
  // decided on before can be counted from here.
  bool ran = false;
  for (int job = 0; job < 100 && !ran; ++job)
    ran = worker_ran_a_part(team);
  ASSERT_TRUE(ran);
  const std::uint64_t before = team.sleeps();
  for (int job = 0; job < 5; ++job) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));  // 40 times its spin
    std::atomic<int> runs{0};
    team.run([&](unsigned) { runs.fetch_add(1); });
    ASSERT_EQ(runs.load(), 2);
  }
  EXPECT_EQ(team.sleeps(), before);
  team.keep_awake(false);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (team.sleeps() == before && std::chrono::steady_clock::now() < deadline)
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  EXPECT_GT(team.sleeps(), before);
}

TEST(Executor, AwakeKeepsTheTeamAwakeForItsScope) {
  Executor exec(2);
  {
    const Executor::Awake awake(exec);
    // Until the worker has run a chunk handed over now, a sleep it decided on before may still be
    // counted.
    std::atomic<int> on_worker{0};
    const std::thread::id caller = std::this_thread::get_id();
    for (int job = 0; job < 100 && on_worker.load() == 0; ++job) {
      std::atomic<bool> started{false};
      exec.for_chunks(2, 1, [&](std::size_t begin, std::size_t) {
        if (begin == 1) {
          started.store(true);
          on_worker += std::this_thread::get_id() != caller;
          return;
        }
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::milliseconds(50);
        while (!started.load() && std::chrono::steady_clock::now() < deadline)
          std::this_thread::sleep_for(std::chrono::microseconds(50));
      });
    }
    ASSERT_GT(on_worker.load(), 0);
    const std::uint64_t before = exec.worker_sleeps();
    for (int job = 0; job < 3; ++job) {
      std::this_thread::sleep_for(std::chrono::milliseconds(2));
      std::atomic<int> chunks{0};
      exec.for_chunks(4, 1, [&](std::size_t, std::size_t) { chunks.fetch_add(1); });
      EXPECT_EQ(chunks.load(), 4);
    }
    EXPECT_EQ(exec.worker_sleeps(), before);
  }
  const Executor serial(1);
  const Executor::Awake nothing(serial);  // no team: nothing to keep awake
  EXPECT_EQ(serial.parts(), 1u);
}

TEST(WorkerTeam, AJobStartedInsideAPartRunsInline) {
  WorkerTeam team(2);
  std::atomic<int> inner{0};
  std::thread::id inner_threads[2][2];
  team.run([&](unsigned p) {
    team.run([&](unsigned q) {
      inner.fetch_add(1);
      inner_threads[p][q] = std::this_thread::get_id();
    });
    // Both inner parts ran on the thread of the outer part that started them.
    EXPECT_EQ(inner_threads[p][0], std::this_thread::get_id());
    EXPECT_EQ(inner_threads[p][1], std::this_thread::get_id());
  });
  EXPECT_EQ(inner.load(), 4);
}

TEST(Executor, SideBySideRunsBothAndChunksCoverTheRangeOnce) {
  for (int threads : {1, 2, 3}) {
    Executor exec(threads);
    std::vector<int> hits(10'000, 0);
    exec.for_chunks(hits.size(), 512, [&](std::size_t begin, std::size_t end) {
      EXPECT_EQ(begin % 512, 0u);
      for (std::size_t i = begin; i < end; ++i)
        ++hits[i];
    });
    for (std::size_t i = 0; i < hits.size(); ++i)
      ASSERT_EQ(hits[i], 1) << i << " with " << threads << " threads";
    int a = 0, b = 0;
    exec.run_side_by_side([&] { ++a; }, [&] { ++b; });
    EXPECT_EQ(a, 1);
    EXPECT_EQ(b, 1);
  }
}

}  // namespace
}  // namespace imasim::physics
