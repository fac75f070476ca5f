// Scene files: the default scene survives print -> parse; broken files give file:line:key errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "physics/executor.hpp"
#include "scene/scene_file.hpp"

namespace imasim::scene {
namespace {

TEST(SceneFile, PrintThenParseGivesTheSameScene) {
  const std::string text = print_scene(default_thorax_scene_params());
  const ThoraxSceneParams parsed = parse_scene(text, "default.toml");
  EXPECT_EQ(print_scene(parsed), text);
  // And the same simulation, bit for bit.
  std::uint64_t hash[2];
  int k = 0;
  for (const ThoraxSceneParams& p : {default_thorax_scene_params(), parsed}) {
    ThoraxScene s = make_thorax_scene(p);
    physics::Executor exec(1);
    for (int n = 0; n < 20; ++n)
      ASSERT_TRUE(step_thorax_scene(s, exec).ok());
    hash[k++] = physics::position_hash(s.patch.world.state);
  }
  EXPECT_EQ(hash[0], hash[1]);
}

TEST(SceneFile, KeysNotGivenKeepTheirDefaults) {
  const ThoraxSceneParams p =
      parse_scene("[heart]\nheart_rate_bpm = 90\nbeating = false\n", "s.toml");
  EXPECT_EQ(p.playback.heart_rate_bpm, 90);
  EXPECT_FALSE(p.playback.beating);
  EXPECT_EQ(p.heart.phases, 11u);
  EXPECT_EQ(p.patch.fascia.nx, default_thorax_scene_params().patch.fascia.nx);
  const ThoraxSceneParams q = parse_scene(
      "[vessel]\ncenterline_m = [[0, 0, 0], [0.01, 0, 0.05], [0, 0, 0.15]]\n[ima_fat]\nseed = 7\n",
      "s.toml");
  ASSERT_EQ(q.patch.vessel.centerline.size(), 3u);
  EXPECT_EQ(q.patch.vessel.centerline[1], Vec3(0.01, 0, 0.05));
  EXPECT_EQ(q.patch.ima_fat.generation.seed, 7u);
}

struct Broken {
  const char* text;
  const char* message;  // expected substring, file:line:key included
};

TEST(SceneFile, BrokenFilesNameFileLineAndKey) {
  const Broken cases[] = {
      {"[heart]\nhart_rate_bpm = 80\n",
       "bad.toml:2: key 'heart.hart_rate_bpm': unknown key; did you mean 'heart.heart_rate_bpm'?"},
      {"[heart]\n\nejection_fraction = 1.5\n",
       "bad.toml:3: key 'heart.ejection_fraction': expected a number in [0.05, 0.95], got 1.5"},
      {"[heart]\ncentre_m = [1, 2]\n", "bad.toml:2: key 'heart.centre_m': expected [x, y, z]"},
      {"[heart]\nbeating = 1\n", "bad.toml:2: key 'heart.beating': expected true or false"},
      {"[solver]\niterations = 2.5\n", "bad.toml:2: key 'solver.iterations': expected an integer"},
      {"[solver]\niterations = 0\n",
       "bad.toml:2: key 'solver.iterations': expected an integer in [1, 1000], got 0"},
      {"[solver]\ndt_s = \"fast\"\n", "bad.toml:2: key 'solver.dt_s': expected a number"},
      {"[vessel]\ncenterline_m = [[0, 0, 0]]\n",
       "bad.toml:2: key 'vessel.centerline_m': expected at least two"},
      {"[vessel]\ncenterline_m = [[0, 0, 0], [1, 1]]\n",
       "bad.toml:2: key 'vessel.centerline_m': point 1 is not [x, y, z]"},
      {"\n[fasica]\nnx = 3\n", "bad.toml:2: unknown table 'fasica'; did you mean 'fascia'?"},
      {"heart_rate_bpm = 70\n",
       "bad.toml:1: key 'heart_rate_bpm': not inside a table; did you mean "
       "'heart.heart_rate_bpm'?"},
      {"[heart\n", "bad.toml:1:"},
      {"[heart]\nphases = 3\nphases = 4\n", "bad.toml:3:"},
  };
  for (const Broken& c : cases) {
    try {
      parse_scene(c.text, "bad.toml");
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const SceneFileError& e) {
      EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << "for\n"
                                                                          << c.text << "got\n"
                                                                          << e.what();
    }
  }
}

TEST(SceneFile, ReportsEveryErrorInFileOrder) {
  try {
    parse_scene("[solver]\niterations = 0\n[heart]\nzzz = 1\naaa = 2\n", "bad.toml");
    FAIL();
  } catch (const SceneFileError& e) {
    ASSERT_EQ(e.messages().size(), 3u);
    EXPECT_EQ(e.messages()[0].rfind("bad.toml:2:", 0), 0u);
    EXPECT_EQ(e.messages()[1].rfind("bad.toml:4:", 0), 0u);
    EXPECT_EQ(e.messages()[2].rfind("bad.toml:5:", 0), 0u);
  }
}

TEST(SceneFile, MissingFileIsAClearError) {
  try {
    load_scene_file("/nonexistent/scene.toml");
    FAIL();
  } catch (const SceneFileError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/scene.toml: cannot open"),
              std::string::npos);
  }
}

TEST(SceneFile, SuggestsByEditDistance) {
  EXPECT_EQ(edit_distance("heart", "hart"), 1u);
  EXPECT_EQ(edit_distance("fasica", "fascia"), 2u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
}

}  // namespace
}  // namespace imasim::scene
