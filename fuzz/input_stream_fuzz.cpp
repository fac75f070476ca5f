// libFuzzer target: recorded input streams (console/input_stream.hpp). Any bytes are either
// refused with InputStreamError or give steps whose text written back reads back to the same
// text (a replay file is exact), with finite poses and powers in range; its origin lines
// (console/stream_origin.hpp) likewise.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "console/input_stream.hpp"
#include "fuzz_check.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace imasim;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  // The origin lines: refused, or an origin that written back reads back the same.
  try {
    const console::StreamHead head = console::read_stream_head(text, "fuzz.stream");
    if (head.origin) {
      const console::StreamHead again =
          console::read_stream_head(console::format_stream_origin(*head.origin), "again");
      fuzz::require(
          again.origin && console::origin_differences(*head.origin, *again.origin).empty(),
          "an origin written back does not read back the same");
    }
  } catch (const console::InputStreamError&) {
  }
  std::vector<session::SessionInput> steps;
  try {
    steps = console::parse_input_stream(text, "fuzz.stream");
  } catch (const console::InputStreamError&) {
    return 0;
  }
  std::string written;
  for (std::size_t k = 0; k < steps.size(); ++k) {
    const session::SessionInput& in = steps[k];
    for (const surgery::InstrumentInput* hand : {&in.left, &in.right}) {
      fuzz::require(hand->pose.translation.allFinite() && hand->pose.rotation.allFinite(),
                    "an accepted pose is not finite");
      fuzz::require(hand->power >= 0 && hand->power <= 300, "an accepted power is out of range");
    }
    written += console::format_input_line(k, in) + '\n';
  }
  const std::vector<session::SessionInput> again = console::parse_input_stream(written, "again");
  std::string rewritten;
  for (std::size_t k = 0; k < again.size(); ++k)
    rewritten += console::format_input_line(k, again[k]) + '\n';
  fuzz::require(rewritten == written, "a stream written back does not read back the same");
  return 0;
}
