// libFuzzer target: input scripts. Any bytes are either refused with InputScriptError or give a
// script whose tracks sample to finite poses at any time, and which repeats.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "fuzz_check.hpp"
#include "surgery/input_script.hpp"
#include "surgery/input_script_repeat.hpp"

namespace {

void check_samples(const imasim::surgery::InputScript& script) {
  using namespace imasim::surgery;
  const double end = script.end_time();
  imasim::fuzz::require(std::isfinite(end) && end >= 0, "a script's end time is not finite");
  for (const double t : {-1.0, 0.0, end * 0.25, end * 0.5, end, end + 1.0}) {
    for (const InstrumentTrack* track : {&script.left, &script.right}) {
      const InstrumentInput in = sample_instrument(*track, t);
      imasim::fuzz::require(in.pose.translation.allFinite() && in.pose.rotation.allFinite(),
                            "a sampled pose is not finite");
    }
    const CameraInput camera = sample_camera(script.camera, t);
    imasim::fuzz::require(std::isfinite(double(camera.optics)) &&
                              std::isfinite(double(camera.insertion.value_or(0))) &&
                              std::isfinite(double(camera.roll.value_or(0))),
                          "a sampled camera command is not finite");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace imasim::surgery;
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  InputScript script;
  try {
    script = parse_input_script(text, "fuzz.script");
  } catch (const InputScriptError&) {
    return 0;
  }
  check_samples(script);
  try {
    check_samples(repeat_input_script(script, 3, script.end_time() + 0.5));
  } catch (const InputScriptError&) {
    // A script near the time limit cannot be repeated: refused, which is the contract.
  }
  return 0;
}
