#pragma once
// Where a recorded input stream came from: the program, the scene (a hash of every key
// as `scene print-default` writes them, so any change shows), the patient seed, the heart's mode,
// the step and the solver, written as "#! key value" lines at the stream's head, and an end line
// "#! end STEPS" written when the stream is closed. A replay under another origin gives another
// state: it is refused naming the field, and a stream without its end line was cut short.
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "scene/thorax_scene.hpp"

namespace imasim::console {

struct StreamOrigin {
  std::string program;     // the program's version
  std::string scene_hash;  // 16 hex digits of print_scene's text
  std::uint64_t patient_seed = 0;
  std::string heart;  // "beating" or "static"
  double dt_s = 0;    // (unit: s)
  std::uint32_t substeps = 0, iterations = 0, stretch_sweeps = 0;
};

// The origin of a run of `params` (after the command line's overrides).
StreamOrigin stream_origin_of(const scene::ThoraxSceneParams& params, std::string program);

// "#! program ...\n#! scene_hash ...\n..." (each value exact: dt in hexadecimal floating point).
std::string format_stream_origin(const StreamOrigin& origin);
std::string format_stream_end(std::uint64_t steps);

// What a stream's "#!" lines say; throws InputStreamError ("PATH:LINE: ...") for a malformed or
// repeated one, or an origin missing a field.
struct StreamHead {
  std::optional<StreamOrigin> origin;      // empty: a stream from before origins were written
  std::optional<std::uint64_t> end_steps;  // the end line's count; empty: no end line
};
StreamHead read_stream_head(std::string_view text, const std::string& path);

// Each field that differs, "heart: recorded static, this run beating", in the order above.
std::vector<std::string> origin_differences(const StreamOrigin& recorded, const StreamOrigin& now);

}  // namespace imasim::console
