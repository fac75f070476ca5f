#pragma once
// Ctrl-C (SIGINT), SIGTERM and SIGHUP end a run cleanly: the handler only records the signal,
// the run loop sees it at the next step, stops, and writes its outputs and report as after a
// normal end (status "interrupted"). A second signal more than a second after the first takes
// the default action, so a run that does not stop can still be killed; one within the second is
// the same request delivered twice (`timeout` signals the child and then its process group) and
// is ignored.
namespace imasim::cli {

void install_interrupt_handlers();

// The signal that asked the run to stop, 0 while none did.
int interrupt_signal();

// The conventional exit status of a process ended by `signal` (128 + signal).
inline int interrupted_exit_status(int signal) {
  return 128 + signal;
}

}  // namespace imasim::cli
