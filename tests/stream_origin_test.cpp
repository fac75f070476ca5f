// Where a recorded input stream came from (console/stream_origin.hpp): the origin lines read back
// exactly, each differing field is named, and malformed "#!" lines are refused with their line.
#include <gtest/gtest.h>

#include "console/input_stream.hpp"
#include "console/stream_origin.hpp"
#include "scene/thorax_scene.hpp"

namespace imasim::console {
namespace {

std::string message_of(const std::string& text) {
  try {
    read_stream_head(text, "s.stream");
  } catch (const InputStreamError& e) {
    return e.what();
  }
  return "";
}

TEST(StreamOrigin, TheOriginAndTheEndReadBackExactly) {
  scene::ThoraxSceneParams params = scene::default_thorax_scene_params();
  params.anatomy.patient_seed = 18'446'744'073'709'551'615u;
  params.playback.beating = false;
  const StreamOrigin o = stream_origin_of(params, "1.2.3");
  EXPECT_EQ(o.heart, "static");
  EXPECT_EQ(o.substeps, params.patch.solver.substeps);
  const std::string text =
      "# comment\n" + format_stream_origin(o) + "0 ...\n" + format_stream_end(7);
  const StreamHead head = read_stream_head(text, "s.stream");
  ASSERT_TRUE(head.origin.has_value());
  EXPECT_TRUE(origin_differences(*head.origin, o).empty());
  EXPECT_EQ(head.origin->dt_s, double(params.patch.solver.dt));
  EXPECT_EQ(head.origin->patient_seed, params.anatomy.patient_seed);
  ASSERT_TRUE(head.end_steps.has_value());
  EXPECT_EQ(*head.end_steps, 7u);
  // No "#!" lines: a stream from before origins.
  const StreamHead plain = read_stream_head("# v1\n0 ...\n", "s.stream");
  EXPECT_FALSE(plain.origin.has_value());
  EXPECT_FALSE(plain.end_steps.has_value());
}

TEST(StreamOrigin, EachDifferingFieldIsNamedAndAnySceneKeyChangesTheHash) {
  const scene::ThoraxSceneParams params = scene::default_thorax_scene_params();
  const StreamOrigin o = stream_origin_of(params, "1.2.3");
  scene::ThoraxSceneParams other = params;
  other.patch.solver.substeps = 64;
  other.anatomy.patient_seed = 5;
  const std::vector<std::string> d = origin_differences(o, stream_origin_of(other, "1.2.3"));
  ASSERT_EQ(d.size(), 3u);
  EXPECT_EQ(d[0], "patient_seed: recorded 0, this run 5");
  EXPECT_EQ(d[1], "substeps: recorded 32, this run 64");
  EXPECT_EQ(d[2].rfind("scene_hash: recorded ", 0), 0u);
  // A key no field names still shows, in the scene's hash.
  scene::ThoraxSceneParams wetter = params;
  wetter.patch.fascia.object.linear_damping = Real(0.05);
  const std::vector<std::string> w = origin_differences(o, stream_origin_of(wetter, "1.2.3"));
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].rfind("scene_hash: ", 0), 0u);
  EXPECT_EQ(origin_differences(o, stream_origin_of(params, "1.2.4")),
            std::vector<std::string>{"program: recorded 1.2.3, this run 1.2.4"});
}

TEST(StreamOrigin, MalformedOriginLinesAreRefusedWithTheirLine) {
  const std::string good =
      format_stream_origin(stream_origin_of(scene::default_thorax_scene_params(), "1.2.3"));
  EXPECT_EQ(message_of("#! heart sideways\n"),
            "s.stream:1: 'heart': not a value of it ('sideways')");
  EXPECT_EQ(message_of("#! colour red\n"), "s.stream:1: unknown origin field 'colour'");
  EXPECT_EQ(message_of("#! heart\n"), "s.stream:1: expected '#! KEY VALUE'");
  EXPECT_EQ(message_of(good + "#! end 3\n#! end 4\n"),
            "s.stream:10: a line after the stream's end line");
  EXPECT_EQ(message_of("#! heart static\n#! heart static\n"), "s.stream:2: 'heart' given twice");
  EXPECT_EQ(message_of("#! heart static\n"), "s.stream: the stream's origin has no 'program' line");
  EXPECT_EQ(message_of("#! end -1\n"), "s.stream:1: the end line's step count is not a count");
  EXPECT_EQ(message_of("#! patient_seed 99999999999999999999\n" + good.substr(good.find('\n') + 1)),
            "s.stream:1: 'patient_seed': not a value of it ('99999999999999999999')");
}

}  // namespace
}  // namespace imasim::console
