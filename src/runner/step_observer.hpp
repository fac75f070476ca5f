#pragma once
// What watches a session's steps (SessionRunner, session_runner.hpp): the input stream's
// recorder and the events file (here), the 60 Hz recording and its scores, the window's frames
// and numbers, a run's own figures. An observer that cannot write its file throws
// metrics::OutputError: the runner stops there and says so, and what was written stays.
#include <cstdint>

#include "physics/step.hpp"
#include "session/surgical_session.hpp"

namespace imasim::runner {

// A step the session took: its input, the physics step's result (with its profile) and its
// wall time.
struct StepRecord {
  const session::SessionInput& input;
  const physics::StepResult& result;
  std::uint64_t step = 0;  // 1 for the first of the session
  double step_ms = 0;      // the input, the observers before it and the step (unit: ms)
};

class StepObserver {
 public:
  virtual ~StepObserver() = default;
  // Before step `step` (0 for the first) is taken, with its input.
  virtual void before_step(const session::SurgicalSession&, const session::SessionInput&,
                           std::uint64_t /*step*/) {}
  // After a step was taken.
  virtual void after_step(const session::SurgicalSession&, const StepRecord&) {}
  // The run is over (however it ended): anything left reaches its file.
  virtual void finish(const session::SurgicalSession&) {}
};

}  // namespace imasim::runner
