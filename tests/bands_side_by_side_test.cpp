// The two rate bands stepped side by side (physics/step.cpp): over each group of substeps (a
// coarse substep and the fine ones it spans) the coarse band reads the fine band's particles as
// the group began, and the proxies as they were then, and what its contacts move a proxy by is
// added when the bands join. Closed-form checks on a falling particle followed by a coarse one,
// and a coarse particle pushing a proxy; the same bits on one thread and two.
#include <gtest/gtest.h>

#include "physics/executor.hpp"
#include "physics/step.hpp"

namespace imasim::physics {
namespace {

constexpr Real kG = Real(9.81);

struct Rig {
  Model model;
  State state;

  Rig() {
    ObjectParams fine;  // falls freely
    fine.gravity = Vec3(0, -kG, 0);
    ObjectParams coarse;  // held by its follow row only
    coarse.gravity = Vec3::Zero();
    coarse.coarse = true;
    model.objects = {fine, coarse};
    model.solver.substeps = 8;
    model.solver.coarse_stride = 4;
    model.solver.iterations = 1;
    state.constraints.set_object_band(1, true);
    state.particles.add(Vec3(0, 1, 0), Real(0.01), 0);  // the source, fine
    state.particles.add(Vec3(1, 1, 0), Real(0.01), 1);  // the follower, coarse
    prepare_state(model, state);
  }
  void follow() { state.follows = {{0, 1, Vec3(0, 1, 0), Vec3(1, 1, 0), Real(1)}}; }
};

TEST(BandsSideBySide, ACoarseFollowerReadsItsFineSourceAsTheGroupBegan) {
  for (int threads : {1, 2}) {
    Rig rig;
    Executor exec(threads);
    rig.follow();
    ASSERT_TRUE(step(rig.model, rig.state, exec).ok());
    // Free fall in the symplectic form: after k substeps of h from rest the source is
    // g h^2 k (k + 1) / 2 below its start. The second coarse substep (substeps 4-7) read it
    // after 4 substeps, not 8: the follower is 10 g h^2 down, the source 36 g h^2.
    const Real h = rig.model.solver.dt / 8;
    const Vec3& source = rig.state.particles.position[0];
    const Vec3& follower = rig.state.particles.position[1];
    EXPECT_NEAR(source.y(), 1 - 36 * kG * h * h, 1e-15) << threads;
    EXPECT_NEAR(follower.y(), 1 - 10 * kG * h * h, 1e-15) << threads;
    EXPECT_DOUBLE_EQ(follower.x(), 1);
  }
}

TEST(BandsSideBySide, AProxyTakesWhatTheCoarseBandsContactsMovedIt) {
  // A coarse particle resting on a proxy's plane (gravity on it this time): the fine band has
  // nothing to do, so the proxy's impulse over the step is the coarse contact's alone.
  for (int threads : {1, 2}) {
    Rig rig;
    rig.model.objects[1].gravity = Vec3(0, -kG, 0);
    ProxyBody proxy;
    proxy.stiffness = 1000;
    proxy.damping = 5;
    rig.state.proxies = {proxy};
    ContactRow row;
    row.particle = 1;
    row.point0 = row.point1 = Vec3(1, 1, 0);
    row.normal = Vec3::UnitY();
    row.body = 0;
    rig.state.contacts.rows = {row};
    Executor exec(threads);
    ASSERT_TRUE(step(rig.model, rig.state, exec).ok());
    const ProxyBody& b = rig.state.proxies[0];
    // The particle pushed the proxy down (its share of each correction) and the proxy's
    // coupling pulled it back: down, and by less than the weight's impulse over the step.
    EXPECT_LT(b.impulse.y(), 0) << threads;
    EXPECT_GT(b.impulse.y(), -Real(0.01) * kG * rig.model.solver.dt) << threads;
    EXPECT_LT(b.offset.y(), 0) << threads;
  }
}

TEST(BandsSideBySide, OneThreadAndTwoGiveTheSameBits) {
  Rig one, two;
  Executor exec_one(1), exec_two(2);
  for (int n = 0; n < 20; ++n) {
    one.follow();
    two.follow();
    ASSERT_TRUE(step(one.model, one.state, exec_one).ok());
    ASSERT_TRUE(step(two.model, two.state, exec_two).ok());
  }
  EXPECT_EQ(position_hash(one.state), position_hash(two.state));
}

}  // namespace
}  // namespace imasim::physics
