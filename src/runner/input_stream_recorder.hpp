#pragma once
// Records each step's input as the input stream (console/input_stream.hpp): the origin's "#!"
// lines first, a line a step before it is taken, the end line when the run is over. Replaying the
// file reproduces the run's state hash bit for bit.
#include <cstdint>

#include "console/stream_origin.hpp"
#include "metrics/output_file.hpp"
#include "runner/step_observer.hpp"

namespace imasim::runner {

class InputStreamRecorder final : public StepObserver {
 public:
  // Writes the header at once; throws metrics::OutputError.
  InputStreamRecorder(metrics::OutputFile file, const console::StreamOrigin& origin);
  void before_step(const session::SurgicalSession& session, const session::SessionInput& input,
                   std::uint64_t step) override;
  void finish(const session::SurgicalSession& session) override;
  std::uint64_t lines() const { return lines_; }

 private:
  metrics::OutputFile file_;
  std::uint64_t lines_ = 0;
  bool finished_ = false;
};

}  // namespace imasim::runner
