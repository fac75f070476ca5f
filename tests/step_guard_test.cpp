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

// Steps `warmup` times with the scene's own model, then once with `bad`, which must be refused
// with `expected` and leave the state exactly as it was.
StepResult expect_refused(scene::ClothScene& s, int threads, int warmup, const Model& bad,
                          StepStatus expected) {
  Executor exec(threads);
  for (int n = 0; n < warmup; ++n)
    EXPECT_TRUE(step(s.model, s.state, exec).ok());
  const Snapshot before = snapshot(s.state);
  const StepResult r = step(bad, s.state, exec);
  EXPECT_EQ(r.status, expected);
  expect_unchanged(before, s.state);
  EXPECT_TRUE(step(s.model, s.state, exec).ok());  // and the state is still usable
  return r;
}

TEST(StepGuard, SpeedLimitFailsTheStepAndKeepsTheState) {
  scene::ClothScene s = small_cloth();
  Model strict = s.model;
  strict.solver.max_speed = 1e-4;  // the sagging cloth moves faster than this
  const StepResult r = expect_refused(s, 1, 20, strict, StepStatus::speed_limit);
  EXPECT_LT(r.particle, s.state.particles.size());
}

TEST(StepGuard, NonFiniteValuesFailTheStepAndKeepTheState) {
  scene::ClothScene s = small_cloth();
  Model broken = s.model;
  broken.objects[0].gravity.y() = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(expect_refused(s, 2, 5, broken, StepStatus::non_finite).substep, 0u);
}

TEST(StepGuard, InfiniteGravityIsReportedNotThrown) {
  scene::ClothScene s = small_cloth();
  Model broken = s.model;
  broken.objects[0].gravity.y() = -std::numeric_limits<double>::infinity();
  expect_refused(s, 1, 0, broken, StepStatus::non_finite);
}

}  // namespace
}  // namespace imasim::physics
