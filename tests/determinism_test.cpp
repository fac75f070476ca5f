// Determinism: the same scene and inputs give bit-for-bit the same state, run after run and for
// 1, 2 and 4 threads.
#include <gtest/gtest.h>

#include "physics/executor.hpp"
#include "physics/step.hpp"
#include "scene/cloth_scene.hpp"

namespace imasim::scene {
namespace {

// Large enough that colour groups exceed the parallel grain and are split across threads.
std::uint64_t run_hash(int threads, physics::Response response) {
  ClothParams p;
  p.n = 100;
  p.response = response;
  p.distance_compliance = 1e-5;
  p.bending_compliance = 1;
  p.substeps = 2;
  p.linear_damping = 0.03;
  ClothScene s = make_cloth_scene(p);
  physics::Executor exec(threads);
  for (int n = 0; n < 60; ++n)
    EXPECT_TRUE(physics::step(s.model, s.state, exec).ok());
  return physics::position_hash(s.state);
}

TEST(Determinism, SameHashAcrossRunsAndThreadCounts) {
  for (const auto response : {physics::Response::pbd, physics::Response::xpbd}) {
    const std::uint64_t reference = run_hash(1, response);
    EXPECT_EQ(run_hash(1, response), reference);
    EXPECT_EQ(run_hash(2, response), reference);
    EXPECT_EQ(run_hash(4, response), reference);
  }
}

TEST(Determinism, HashSeesADifferentInput) {
  EXPECT_NE(run_hash(1, physics::Response::pbd), run_hash(1, physics::Response::xpbd));
}

}  // namespace
}  // namespace imasim::scene
