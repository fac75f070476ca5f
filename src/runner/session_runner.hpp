#pragma once
// The one loop that steps a surgical session: each step takes its input from an InputSource
// (input_source.hpp), shows it to the observers (step_observer.hpp), steps the session
// (session::step_session) and shows them the result; paced as fast as the machine steps, or in
// real time (step k due k dt after the first). `imasim run`, `render`, `haptics-bench` and the
// window's physics thread all drive their sessions through it.
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "physics/executor.hpp"
#include "runner/input_source.hpp"
#include "runner/step_observer.hpp"

namespace imasim::runner {

enum class Pacing { as_fast_as_possible, real_time };

// How one step went.
struct StepOutcome {
  physics::StepResult result;  // the physics step's (not ok: the step was refused)
  bool stepped = false;        // the session took the step
  std::string output_error;    // an observer could not write its file (the run stops)
  double step_ms = 0;  // wall time of the input, the observers before it and the step (unit: ms)
  bool ok() const { return stepped && result.ok() && output_error.empty(); }
};

// How a run went: the steps taken, and why it stopped before its count if it did.
struct RunOutcome {
  std::uint64_t steps = 0;
  physics::StepResult failure;  // the refused step's result (ok when none was refused)
  std::string output_error;     // the observer's message when one could not write
  bool stopped = false;         // stop() asked for it (an interrupt)
};

class SessionRunner {
 public:
  // Keeps references: the session, input and executor outlive the runner.
  SessionRunner(session::SurgicalSession& session, InputSource& input, physics::Executor& exec,
                Pacing pacing = Pacing::as_fast_as_possible);

  // Observers see each step in the order they were added.
  void observe(StepObserver& observer) { observers_.push_back(&observer); }
  // The observer sees no more steps (it is not told finish()).
  void forget(const StepObserver& observer) { std::erase(observers_, &observer); }
  // Changes the input's step before the session takes it (the window's optics slider).
  void adjust_input(std::function<void(session::SessionInput&)> adjust) {
    adjust_ = std::move(adjust);
  }

  // One step: input, observers' before_step, the session's step, observers' after_step, the
  // input's after_step, then the pacing's wait.
  StepOutcome step();
  // Up to `steps` steps (fewer when the input ends), stopping early at a refused step, an
  // observer's output error or when `stop` (checked before each step) says so. Observers are
  // told finish() at the end.
  RunOutcome run(std::uint64_t steps, const std::function<bool()>& stop = {});
  // Tells the observers the run is over; returns the first output error (empty if none).
  std::string finish();
  // A new session in place of the old (the window's restart): the count and the input restart.
  void restart(session::SurgicalSession& session);
  // Real time: the next step is due one dt after now (after a pause, or a new session).
  void repace() { repace_ = true; }
  // Real time: behind by more than this, the pacing starts afresh instead of running steps back
  // to back to catch up (unit: s; the default, never: a live run catches up).
  void set_max_lag(double seconds) { max_lag_s_ = seconds; }

  std::uint64_t steps_done() const { return steps_; }
  const session::SessionInput& last_input() const { return input_; }
  session::SurgicalSession& session() { return *session_; }

 private:
  session::SurgicalSession* session_;
  InputSource& source_;
  physics::Executor& exec_;
  Pacing pacing_;
  std::vector<StepObserver*> observers_;
  std::function<void(session::SessionInput&)> adjust_;
  session::SessionInput input_;
  std::uint64_t steps_ = 0;
  // Real time: step base_steps_ + k is due at base_s_ + k dt (steady clock; unit: s).
  double base_s_ = 0;
  std::uint64_t base_steps_ = 0;
  bool repace_ = true;
  double max_lag_s_ = std::numeric_limits<double>::infinity();
};

}  // namespace imasim::runner
