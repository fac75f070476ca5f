#include "interrupt.hpp"

#include <atomic>
#include <csignal>

namespace imasim::cli {
namespace {

std::atomic<int> g_signal{0};
static_assert(std::atomic<int>::is_always_lock_free, "used from a signal handler");

extern "C" void on_interrupt(int signal) {
  g_signal.store(signal, std::memory_order_relaxed);
}

}  // namespace

void install_interrupt_handlers() {
  struct sigaction action {};
  action.sa_handler = on_interrupt;
  sigemptyset(&action.sa_mask);
  // One shot: a second signal takes the default action if the run did not stop.
  action.sa_flags = SA_RESETHAND;
  for (int s : {SIGINT, SIGTERM, SIGHUP})
    sigaction(s, &action, nullptr);
}

int interrupt_signal() {
  return g_signal.load(std::memory_order_relaxed);
}

}  // namespace imasim::cli
