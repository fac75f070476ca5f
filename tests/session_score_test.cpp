// The score card carries the session's counts as they are: strands divided by the hook and
// strands torn by pulling are counted apart (a torn strand is rough handling, not progress).
#include <gtest/gtest.h>

#include "haptics/force_params.hpp"
#include "scene/thorax_scene.hpp"
#include "session/surgical_session.hpp"
#include "ui/session_score.hpp"

namespace imasim::ui {
namespace {

TEST(SessionScore, TheCardCountsDividedAndTornStrandsApart) {
  session::SurgicalSession s =
      session::make_surgical_session(scene::default_thorax_scene_params(), {});
  s.strands_cut = 5;
  s.strands_torn = 2;
  const SessionScore score(s, haptics::default_force_model_params(), Real(1.5e-3));
  const ScoreCard c = score.score_card(s);
  EXPECT_EQ(c.strands_cut, 5u);
  EXPECT_EQ(c.strands_torn, 2u);
  const tissue::TissueWorld& w = s.scene.patch.world;
  EXPECT_EQ(c.strands_total, w.strands[s.scene.patch.ima_fat].strand_count +
                                 w.strands[s.scene.patch.fascia_fat].strand_count);
}

}  // namespace
}  // namespace imasim::ui
