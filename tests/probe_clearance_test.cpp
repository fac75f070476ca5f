// The instruments' stops remember what each probe point's last search of the heart proved
// (session::ProbeClearance): a check the bound answers is not searched. The answers must be the
// searches' own: a hook driven into the beating heart and riding on it moves, bit for bit, as in
// a session whose stops search at every check, and most checks are answered by the bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "physics/executor.hpp"
#include "session/probe_clearance.hpp"
#include "session/surgical_session.hpp"
#include "tissue/heart.hpp"

namespace imasim::session {
namespace {

// Points held still or wandering 0.3 mm a step, from 3 mm inside the beating heart's surface to
// 8 mm outside it, each a probe of its own: every answer is the search's, and some are the
// bound's. (Leaving the heart's travel out of the bound gives wrong answers here: the heart
// beats into still points it had left clear.)
TEST(ProbeClearance, AnswersAsTheSearchOfTheBeatingHeart) {
  const tissue::HeartModel model = tissue::make_procedural_heart(tissue::HeartParams{});
  tissue::HeartField cached = tissue::make_heart_field(model, tissue::HeartPlayback{});
  tissue::HeartField plain = cached;
  tissue::TissueWorld world;  // no anchors: only the heart moves
  constexpr Real kClearance = 0.0005, kSearch = 0.01;
  std::mt19937 rng(11);
  std::uniform_real_distribution<Real> unit(-1, 1);
  std::vector<Vec3> points;
  for (std::size_t v = 0; v < cached.current.size(); v += 7)
    points.push_back(cached.current[v] +
                     Real(0.0055) * (unit(rng) + Real(0.45)) * cached.normals[v]);
  std::vector<ProbeClearance> probes((points.size() + 2) / 3);
  std::size_t near = 0, mismatches = 0;
  for (int step = 1; step <= 400; ++step) {
    tissue::advance_heart(cached, world, step * 0.005);
    tissue::advance_heart(plain, world, step * 0.005);
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (i % 2 == 0) points[i] += Real(0.0003) * Vec3(unit(rng), unit(rng), unit(rng));
      const bool answer =
          nearer_the_heart_than(cached, probes[i / 3], i % 3, points[i], kClearance, kSearch);
      const bool searched = tissue::heart_signed_distance(plain, points[i], kSearch) < kClearance;
      near += searched ? 1 : 0;
      mismatches += answer == searched ? 0 : 1;
    }
  }
  EXPECT_EQ(mismatches, 0u);
  EXPECT_GT(near, 1000u);  // many answers were "too near"
  std::uint64_t searched = 0, skipped = 0;
  for (const ProbeClearance& p : probes) {
    searched += p.searched;
    skipped += p.skipped;
  }
  EXPECT_EQ(searched + skipped, 400 * points.size());
  // Spared only where the search saw both ventricles (near the septum, about one in eight here).
  EXPECT_GT(10 * skipped, searched);
}

TEST(ProbeClearance, TheStopsAnswerAsIfTheySearchedEveryTime) {
  SurgicalSession cached =
      make_surgical_session(scene::default_thorax_scene_params(), SessionParams{});
  SurgicalSession searching =
      make_surgical_session(scene::default_thorax_scene_params(), SessionParams{});
  ASSERT_TRUE(cached.scene.heart.playback.beating);
  physics::Executor exec(1);
  SessionInput in;
  in.right.source = surgery::PoseSource::tool;
  in.right.pose = cached.stations[1].pose;
  const Vec3 start = in.right.pose.translation;
  // Beside the vessel, towards the heart until it stops the hook; then held 0.5 mm back from
  // there, clear of the heart, while it beats into the hook and away: a bound that left out the
  // heart's travel would call the hook clear when the heart has come to it.
  const Vec3 target =
      cached.scene.layout.ima_midpoint +
      Real(0.8) * (cached.scene.layout.heart_centre - cached.scene.layout.ima_midpoint);
  const Vec3 towards = (target - start).normalized();
  int stopped = 0, stopped_while_held = 0;
  for (int n = 1; n <= 60 + 140; ++n) {
    if (n <= 60) in.right.pose.translation = start + (target - start) * (n / 60.0);
    if (n == 60) in.right.pose.translation = cached.stations[1].pose.translation - 0.0005 * towards;
    for (Station& st : searching.stations)
      st.heart_probes = ProbeClearance{};  // nothing known: every check searches
    ASSERT_TRUE(step_session(cached, in, exec).ok());
    ASSERT_TRUE(step_session(searching, in, exec).ok());
    for (std::size_t k = 0; k < cached.stations.size(); ++k) {
      const Station &a = cached.stations[k], &b = searching.stations[k];
      ASSERT_EQ(a.pose.translation, b.pose.translation) << "step " << n << ", station " << k;
      ASSERT_EQ(a.pose.rotation, b.pose.rotation) << "step " << n << ", station " << k;
      ASSERT_EQ(a.blocked_by_heart, b.blocked_by_heart) << "step " << n << ", station " << k;
      ASSERT_EQ(a.stop.point, b.stop.point) << "step " << n << ", station " << k;
    }
    stopped += cached.stations[1].blocked_by_heart ? 1 : 0;
    if (n > 60) stopped_while_held += cached.stations[1].blocked_by_heart ? 1 : 0;
  }
  EXPECT_GT(stopped, 0);             // the heart stopped the hook on its way
  EXPECT_GT(stopped_while_held, 0);  // and came to the still hook while it beat
  EXPECT_EQ(searching.stations[0].heart_probes.skipped, 0u);
  // The forceps, held where they started, clear of the heart: most of their checks are answered
  // by the bound (386 of 600 when written); the hook's, beside and on the heart, some.
  const ProbeClearance& forceps = cached.stations[0].heart_probes;
  const ProbeClearance& hook = cached.stations[1].heart_probes;
  EXPECT_GT(forceps.skipped, forceps.searched);
  EXPECT_GT(hook.skipped, 0u);
  EXPECT_GT(hook.searched, 0u);
}

}  // namespace
}  // namespace imasim::session
