#pragma once
// Whether `imasim run --replay STREAM` may play a recorded stream: a stream replayed
// under another program, scene, patient, heart mode or solver gives another state, and one cut
// short or empty replays less than was recorded, each with exit 0 until now. Refused naming the
// field or the cause, unless --replay-anyway (then said on stderr); an empty stream always.
#include <string>
#include <vector>

#include "console/input_stream.hpp"

namespace imasim::cli {

struct ReplayVerdict {
  bool refused = false;
  std::vector<std::string> lines;  // for stderr, each naming the stream
};

ReplayVerdict check_replay(const console::RecordedStream& stream, const std::string& path,
                           const console::StreamOrigin& now, bool anyway);

}  // namespace imasim::cli
