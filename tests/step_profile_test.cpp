// The step's profile: each layer times its own stages, the stages are disjoint laps of one clock
// (their sum is the step's wall time, never more), and timing changes no result.
#include <gtest/gtest.h>

#include <chrono>

#include "physics/executor.hpp"
#include "physics/step.hpp"
#include "scene/cloth_scene.hpp"
#include "session/surgical_session.hpp"

namespace imasim {
namespace {

using physics::Stage;

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

TEST(StepProfile, TheEngineTimesItsOwnStagesOnly) {
  scene::ClothParams p;
  p.n = 16;
  p.substeps = 4;
  scene::ClothScene cloth = scene::make_cloth_scene(p);
  physics::Executor exec(1);
  const auto t0 = std::chrono::steady_clock::now();
  const physics::StepResult r = physics::step(cloth.model, cloth.state, exec);
  const double wall = seconds_since(t0);
  ASSERT_TRUE(r.ok());
  for (Stage s : {Stage::predict, Stage::solve, Stage::contacts, Stage::velocities})
    EXPECT_GT(r.profile[s], 0.0) << physics::to_string(s);
  for (Stage s :
       {Stage::instruments, Stage::cutting, Stage::heart, Stage::coupling, Stage::surfaces})
    EXPECT_EQ(r.profile[s], 0.0) << physics::to_string(s);
  EXPECT_LE(r.profile.total(), wall);
}

TEST(StepProfile, ASessionAccountsForItsStepsStageByStage) {
  session::SurgicalSession s = session::make_surgical_session(scene::default_thorax_scene_params(),
                                                              session::SessionParams{});
  physics::Executor exec(1);
  constexpr int kSteps = 20;
  double wall = 0;
  for (int n = 0; n < kSteps; ++n) {
    const auto t0 = std::chrono::steady_clock::now();
    const physics::StepResult r = session::step_session(s, session::SessionInput{}, exec);
    wall += seconds_since(t0);
    ASSERT_TRUE(r.ok());
  }
  EXPECT_EQ(s.profile.steps, std::uint64_t(kSteps));
  for (std::size_t k = 0; k < physics::kStageCount; ++k) {
    const auto stage = static_cast<Stage>(k);
    EXPECT_GT(s.profile.sum[stage], 0.0) << physics::to_string(stage);
    EXPECT_LE(s.profile.max[stage], s.profile.sum[stage]) << physics::to_string(stage);
  }
  // Laps of one clock: together they cover the step (what lies between them is a few clock
  // reads) and never count a moment twice.
  EXPECT_LE(s.profile.sum.total(), wall);
  EXPECT_GE(s.profile.sum.total(), 0.9 * wall);
  EXPECT_GT(s.profile.mean(Stage::solve), 0.0);
}

TEST(StepProfile, ProfileTotalsKeepSumsMaximaAndMeans) {
  physics::ProfileTotals totals;
  physics::StepProfile a, b;
  a[Stage::solve] = 2e-3;
  a[Stage::predict] = 1e-3;
  b[Stage::solve] = 4e-3;
  totals.add(a);
  totals.add(b);
  EXPECT_EQ(totals.steps, 2u);
  EXPECT_DOUBLE_EQ(totals.sum[Stage::solve], 6e-3);
  EXPECT_DOUBLE_EQ(totals.max[Stage::solve], 4e-3);
  EXPECT_DOUBLE_EQ(totals.max[Stage::predict], 1e-3);
  EXPECT_DOUBLE_EQ(totals.mean(Stage::solve), 3e-3);
  EXPECT_DOUBLE_EQ(totals.max_total, 4e-3);
  EXPECT_EQ(physics::ProfileTotals{}.mean(Stage::solve), 0.0);
}

}  // namespace
}  // namespace imasim
