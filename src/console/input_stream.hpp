#pragma once
// A recorded device stream: the session input of every step, as the
// devices gave it, written exactly (hexadecimal floating point) so that replaying the file
// through step_session reproduces the run's state hash bit for bit. Text, one line a step:
//   <step> <left> <right> <camera> [lost:left|lost:right|lost:both]
//   instrument: <source none|hand|tool> <x y z> <r00 .. r22> <jaw -1|0|1> <clutch 0|1>
//               <pedal off|cut|coag> <power W>
//   camera: <optics rad> <insertion m or -> <roll rad or ->
//   lost: the steps on which a hand's device (or the pedal's, for the right) was gone
// Lines starting with '#' are comments; "#!" lines say where the stream came from and where it
// ends (console/stream_origin.hpp). Reading checks everything up front and throws
// InputStreamError ("PATH:LINE: message").
#include <cstdio>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "console/stream_origin.hpp"
#include "session/surgical_session.hpp"

namespace imasim::console {

class InputStreamError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// One step's line, without the newline.
std::string format_input_line(std::uint64_t step, const session::SessionInput& input);

// Every step's input, in order; `path` only prefixes the messages.
std::vector<session::SessionInput> parse_input_stream(std::string_view text,
                                                      const std::string& path);
std::vector<session::SessionInput> load_input_stream(const std::string& path);

// A recorded stream with what its "#!" lines say of its origin and its end (stream_origin.hpp).
struct RecordedStream {
  StreamHead head;
  std::vector<session::SessionInput> steps;
};
RecordedStream load_recorded_stream(const std::string& path);

}  // namespace imasim::console
