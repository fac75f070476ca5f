#include "runner/session_runner.hpp"

#include <chrono>
#include <thread>

#include "metrics/output_file.hpp"

namespace imasim::runner {

namespace {

double now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

}  // namespace

SessionRunner::SessionRunner(session::SurgicalSession& session, InputSource& input,
                             physics::Executor& exec, Pacing pacing)
    : session_(&session), source_(input), exec_(exec), pacing_(pacing) {}

StepOutcome SessionRunner::step() {
  StepOutcome out;
  const double t0 = now_s();
  if (repace_) base_s_ = t0, base_steps_ = steps_, repace_ = false;
  input_ = source_.next(*session_);
  if (adjust_) adjust_(input_);
  try {
    for (StepObserver* o : observers_)
      o->before_step(*session_, input_, steps_);
  } catch (const metrics::OutputError& e) {
    out.output_error = e.what();
    return out;
  }
  out.result = session::step_session(*session_, input_, exec_);
  out.step_ms = 1000 * (now_s() - t0);
  if (!out.result.ok()) return out;
  out.stepped = true;
  ++steps_;
  try {
    const StepRecord record{input_, out.result, steps_, out.step_ms};
    for (StepObserver* o : observers_)
      o->after_step(*session_, record);
  } catch (const metrics::OutputError& e) {
    out.output_error = e.what();
  }
  source_.after_step(*session_, steps_);
  if (pacing_ == Pacing::real_time) {
    const double dt = double(session_->scene.patch.world.model.solver.dt);
    const double wait = base_s_ + double(steps_ - base_steps_) * dt - now_s();
    if (wait > 0)
      std::this_thread::sleep_for(std::chrono::duration<double>(wait));
    else if (-wait > max_lag_s_)
      repace_ = true;
  }
  return out;
}

RunOutcome SessionRunner::run(std::uint64_t steps, const std::function<bool()>& stop) {
  RunOutcome out;
  if (const std::optional<std::uint64_t> length = source_.length(); length && *length < steps)
    steps = *length;
  const std::uint64_t first = steps_;
  while (steps_ - first < steps) {
    if (stop && stop()) {
      out.stopped = true;
      break;
    }
    const StepOutcome s = step();
    if (!s.result.ok()) {
      out.failure = s.result;
      break;
    }
    if (!s.output_error.empty()) {
      out.output_error = s.output_error;
      break;
    }
  }
  out.steps = steps_ - first;
  const std::string left = finish();
  if (out.output_error.empty()) out.output_error = left;
  return out;
}

std::string SessionRunner::finish() {
  std::string error;
  for (StepObserver* o : observers_) {
    try {
      o->finish(*session_);
    } catch (const metrics::OutputError& e) {
      if (error.empty()) error = e.what();
    }
  }
  return error;
}

void SessionRunner::restart(session::SurgicalSession& session) {
  session_ = &session;
  steps_ = 0;
  repace_ = true;
  source_.restart();
}

}  // namespace imasim::runner
