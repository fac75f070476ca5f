// The divergence guard: a failing step reports why and leaves the state exactly as it was.
#include <gtest/gtest.h>

#include <limits>

#include "physics/executor.hpp"
#include "physics/step.hpp"
#include "scene/cloth_scene.hpp"

namespace imasim::physics {
namespace {

struct Snapshot {
  std::vector<Vec3> position, velocity;
  double time;
  std::uint64_t steps;
};

Snapshot snapshot(const State& s) {
  return {s.particles.position, s.particles.velocity, s.time, s.step_count};
}

void expect_unchanged(const Snapshot& before, const State& s) {
  EXPECT_EQ(before.position, s.particles.position);
  EXPECT_EQ(before.velocity, s.particles.velocity);
  EXPECT_EQ(before.time, s.time);
  EXPECT_EQ(before.steps, s.step_count);
}

scene::ClothScene small_cloth() {
  scene::ClothParams p;
  p.n = 8;
  p.substeps = 3;
  return scene::make_cloth_scene(p);
}

TEST(StepGuard, SpeedLimitFailsTheStepAndKeepsTheState) {
  scene::ClothScene s = small_cloth();
  Executor exec(1);
  for (int n = 0; n < 20; ++n)
    ASSERT_TRUE(step(s.model, s.state, exec).ok());
  const Snapshot before = snapshot(s.state);
  Model strict = s.model;
  strict.solver.max_speed = 1e-4;  // the sagging cloth moves faster than this
  const StepResult r = step(strict, s.state, exec);
  EXPECT_EQ(r.status, StepStatus::speed_limit);
  EXPECT_LT(r.particle, s.state.particles.size());
  expect_unchanged(before, s.state);
  EXPECT_TRUE(step(s.model, s.state, exec).ok());  // and the state is still usable
}

TEST(StepGuard, NonFiniteValuesFailTheStepAndKeepTheState) {
  scene::ClothScene s = small_cloth();
  Executor exec(2);
  for (int n = 0; n < 5; ++n)
    ASSERT_TRUE(step(s.model, s.state, exec).ok());
  const Snapshot before = snapshot(s.state);
  Model broken = s.model;
  broken.objects[0].gravity.y() = std::numeric_limits<double>::quiet_NaN();
  const StepResult r = step(broken, s.state, exec);
  EXPECT_EQ(r.status, StepStatus::non_finite);
  EXPECT_EQ(r.substep, 0u);
  expect_unchanged(before, s.state);
}

TEST(StepGuard, InfiniteGravityIsReportedNotThrown) {
  scene::ClothScene s = small_cloth();
  Executor exec(1);
  Model broken = s.model;
  broken.objects[0].gravity.y() = -std::numeric_limits<double>::infinity();
  const Snapshot before = snapshot(s.state);
  EXPECT_EQ(step(broken, s.state, exec).status, StepStatus::non_finite);
  expect_unchanged(before, s.state);
}

}  // namespace
}  // namespace imasim::physics
