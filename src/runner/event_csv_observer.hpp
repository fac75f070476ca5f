#pragma once
// Writes the session's events (surgery/events.hpp) to the events CSV as they happen, flushing
// about once a second, the rest when the run is over.
#include "metrics/event_csv.hpp"
#include "runner/step_observer.hpp"

namespace imasim::runner {

class EventCsvObserver final : public StepObserver {
 public:
  explicit EventCsvObserver(metrics::EventCsvWriter writer) : writer_(std::move(writer)) {}
  void after_step(const session::SurgicalSession& session, const StepRecord&) override {
    writer_.append_new(session.events);
  }
  void finish(const session::SurgicalSession& session) override {
    if (finished_) return;
    finished_ = true;
    writer_.finish(session.events);
  }
  const metrics::EventCsvWriter& writer() const { return writer_; }

 private:
  metrics::EventCsvWriter writer_;
  bool finished_ = false;
};

}  // namespace imasim::runner
