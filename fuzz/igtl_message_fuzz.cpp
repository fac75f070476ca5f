// libFuzzer target: OpenIGTLink messages as a device sends them. The bytes are a stream of
// messages (header, then the body its header declares); each is read as imasim's link reads it.
// Any bytes are either refused (and counted) or change the console input to finite values in
// range, never a crash, an unbounded allocation or a hang.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "devices/igtl_codec.hpp"
#include "fuzz_check.hpp"

namespace {

void check_input(const imasim::devices::ConsoleInput& in) {
  using imasim::fuzz::require;
  for (const imasim::devices::HandInput* h : {&in.left, &in.right}) {
    require(h->pose.translation.allFinite() && h->pose.rotation.allFinite(),
            "an accepted pose is not finite");
    require(h->jaw >= 0 && h->jaw <= 1, "an accepted jaw is out of [0, 1]");
    require(std::isfinite(h->time_s) || !h->has_pose, "an accepted pose has no finite time");
  }
  require(int(in.pedal) >= 0 && int(in.pedal) <= 2, "an accepted pedal mode is unknown");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace imasim::devices;
  IgtlDecoder decoder;
  ConsoleInput input;
  std::size_t at = 0;
  while (size - at >= kIgtlHeaderBytes) {
    const std::optional<IgtlHeader> header = decoder.read_header(data + at);
    if (!header) break;  // the link drops a peer that sends a non-header
    const std::size_t body = std::size_t(header->body_bytes);
    const std::size_t available = size - at - kIgtlHeaderBytes;
    const std::size_t given = body <= available ? body : available;  // a truncated last message
    decoder.apply(data + at, data + at + kIgtlHeaderBytes, given, input);
    check_input(input);
    at += kIgtlHeaderBytes + given;
  }
  const IgtlCounters& c = decoder.counters();
  imasim::fuzz::require(c.accepted + c.refused_total() >= 0, "counters");
  return 0;
}
