#include "interrupt.hpp"

#include <atomic>
#include <csignal>
#include <ctime>

namespace imasim::cli {
namespace {

std::atomic<int> g_signal{0};
std::atomic<long long> g_first_ns{0};  // CLOCK_MONOTONIC time of the first signal
static_assert(std::atomic<int>::is_always_lock_free, "used from a signal handler");
static_assert(std::atomic<long long>::is_always_lock_free, "used from a signal handler");

// A repeat within this time is the same request delivered twice (`timeout` signals its child
// and then the child's process group), not a user asking again.
constexpr long long kRepeatIgnoredNs = 1'000'000'000;

long long monotonic_ns() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);  // async-signal-safe
  return static_cast<long long>(t.tv_sec) * 1'000'000'000 + t.tv_nsec;
}

extern "C" void on_interrupt(int signal) {
  const long long now = monotonic_ns();
  int expected = 0;
  if (g_signal.compare_exchange_strong(expected, signal)) {
    g_first_ns.store(now);
    return;
  }
  if (now - g_first_ns.load() < kRepeatIgnoredNs) return;
  // Asked again: the default action (the run did not stop in time for this user).
  std::signal(signal, SIG_DFL);
  std::raise(signal);
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  for (int s : {SIGINT, SIGTERM, SIGHUP})
    sigaction(s, &action, nullptr);
}

int interrupt_signal() {
  return g_signal.load(std::memory_order_relaxed);
}

}  // namespace imasim::cli
