#include "runner/input_stream_recorder.hpp"

#include "console/input_stream.hpp"

namespace imasim::runner {

InputStreamRecorder::InputStreamRecorder(metrics::OutputFile file,
                                         const console::StreamOrigin& origin)
    : file_(std::move(file)) {
  file_.write("# imasim input stream v2: one line a 5 ms step (docs/haptics.md)\n" +
              console::format_stream_origin(origin));
}

void InputStreamRecorder::before_step(const session::SurgicalSession&,
                                      const session::SessionInput& input, std::uint64_t step) {
  file_.write(console::format_input_line(step, input) + '\n');
  ++lines_;
  file_.flush_if_due();
}

void InputStreamRecorder::finish(const session::SurgicalSession&) {
  if (finished_) return;
  finished_ = true;
  file_.write(console::format_stream_end(lines_));
  file_.close();
}

}  // namespace imasim::runner
