// A proxy body stopped by a kinematic surface (physics/body_stop.hpp): pressed past a still
// surface it rests on it and pushes with eq. 17's spring, a surface moving into it pushes it out
// within the step, and friction holds it below Coulomb's bound and slides it at the bound.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/executor.hpp"
#include "physics/step.hpp"
#include "physics/validation.hpp"

namespace imasim::physics {
namespace {

constexpr Real kStiffness = 400;  // k (unit: N/m), the heart's k_d
constexpr Real kDamping = 3;      // c (unit: N s/m), the heart's c_d
constexpr Real kMargin = 0.0005;  // the tool's clearance (unit: m)
constexpr Real kFriction = 0.1;   // the heart's mu

struct Rig {
  Model model;
  State state;
  Executor exec{1};
  // The device's point (the hinge) at the step's start and end; the surface y = surface_y,
  // moving to surface_y + surface_step over each step.
  Vec3 device0 = Vec3::Zero(), device1 = Vec3::Zero();
  Real surface_y = 0, surface_step = 0;

  Rig() {
    model.objects.push_back(ObjectParams{});
    model.solver.substeps = 32;
    model.solver.iterations = 1;
    state.particles.add(Vec3(0, 1, 0), 0.001, 0);  // far away: the rows are the body's alone
    ProxyBody b;
    b.stiffness = kStiffness;
    b.damping = kDamping;
    state.proxies.push_back(b);
  }

  // The row as the session gathers it: the point on the tool's path, which already carries the
  // offset the body starts the step with.
  void gather() {
    state.body_stops.clear();
    BodyStopRow r;
    r.point0 = device0 + body().offset;
    r.point1 = device1 + body().offset;
    r.surface0 = Vec3(0, surface_y, 0);
    r.surface1 = Vec3(0, surface_y + surface_step, 0);
    r.normal = Vec3::UnitY();
    r.margin = kMargin;
    r.static_friction = r.kinetic_friction = kFriction;
    state.body_stops.push_back(r);
  }
  void run(int steps, const Vec3& device_step = Vec3::Zero()) {
    for (int n = 0; n < steps; ++n) {
      device0 = device1;
      device1 = device0 + device_step;
      gather();
      ASSERT_TRUE(step(model, state, exec).ok());
      surface_y += surface_step;
    }
  }
  ProxyBody& body() { return state.proxies[0]; }
  const BodyStopRow& row() const { return state.body_stops[0]; }
  Vec3 point() { return device1 + body().offset; }  // the proxy's hinge where the step ended
  Real h() const { return model.solver.dt / Real(model.solver.substeps); }
  Vec3 force() { return body().impulse / model.solver.dt; }  // on the tool, mean over the step
};

TEST(BodyStop, AProxyPressedPastAStillSurfaceRestsOnItAndPushesWithTheSpring) {
  Rig rig;
  const Real depth = 0.005;  // the device 5 mm into the surface
  rig.device0 = rig.device1 = Vec3(0, -depth, 0);
  rig.run(100);
  // The proxy rests on the surface, the margin above it ...
  EXPECT_NEAR(rig.point().y(), kMargin, 1e-12);
  EXPECT_NEAR(rig.body().offset.y(), depth + kMargin, 1e-12);
  EXPECT_EQ(rig.body().offset.x(), 0);
  // ... and the surface carries the spring, evaluated where each substep's coupling leaves it:
  // k o c / (c + k h), within k h / c (2 %) of eq. 17's k d (d the device's depth past the
  // proxy, depth + margin).
  const Real d = depth + kMargin;
  const Real discrete = kStiffness * d * kDamping / (kDamping + kStiffness * rig.h());
  EXPECT_NEAR(rig.force().y(), discrete, 1e-9 * discrete);
  EXPECT_NEAR(rig.row().normal_impulse / rig.model.solver.dt, discrete, 1e-9 * discrete);
  EXPECT_NEAR(rig.force().y() / (kStiffness * d) - 1, 0, 0.025);
  EXPECT_GT(rig.row().depth, 0);
  // Drawn back out, nothing pushes: the proxy returns to the device and the force to zero.
  rig.device0 = rig.device1 = Vec3(0, 0.003, 0);
  rig.run(20);
  EXPECT_EQ(rig.force(), Vec3::Zero());
  EXPECT_EQ(rig.row().normal_impulse, 0);
  EXPECT_LT(rig.body().offset.norm(), 1e-6);
}

TEST(BodyStop, ASurfaceMovingIntoTheProxyPushesItOutWithinTheStep) {
  Rig rig;
  rig.device0 = rig.device1 = Vec3(0, kMargin, 0);  // resting on the surface, nothing pressed
  rig.surface_step = 0.0002;                        // 40 mm/s towards the tool, as the heart
  for (int n = 0; n < 20; ++n) {
    rig.run(1);
    // Where each step ends, the proxy is the margin above the surface: never inside it.
    EXPECT_NEAR(rig.point().y(), rig.surface_y + kMargin, 1e-12) << n;
    EXPECT_GT(rig.force().y(), 0) << n;
  }
  // The coupling pulls the proxy back to the device: the surface pushes with the spring over
  // the offset at the step's middle, o - v dt / 2, plus the damper's c v.
  const Real v = rig.surface_step / rig.model.solver.dt;
  const Real o = rig.body().offset.y() - v * rig.model.solver.dt / 2;
  EXPECT_NEAR(rig.force().y(), kStiffness * o + kDamping * v, 0.03 * (kStiffness * o));
}

TEST(BodyStop, FrictionHoldsTheProxyBelowCoulombsBoundAndSlidesItAtTheBound) {
  Rig rig;
  const Real depth = 0.005;
  rig.device0 = rig.device1 = Vec3(0, -depth, 0);
  rig.run(60);
  const Real x = rig.point().x();
  // The device moves 0.2 mm along the surface: the spring's pull across, k 0.2 mm, is below mu
  // times its push, mu k 5.5 mm, so the proxy stays where it is.
  rig.run(1, Vec3(0.0002, 0, 0));
  rig.run(40);
  EXPECT_NEAR(rig.point().x(), x, 1e-12);
  EXPECT_LT(std::abs(rig.force().x()), kFriction * rig.force().y());
  EXPECT_GT(std::abs(rig.force().x()), 0.5 * kStiffness * 0.0002);
  // Dragged along at 20 mm/s, it slides: the surface's drag is mu times its push, against the
  // motion.
  rig.run(60, Vec3(0.0001, 0, 0));
  EXPECT_NEAR(rig.force().x(), -kFriction * rig.force().y(), 1e-9 * rig.force().y());
  EXPECT_NEAR(rig.row().friction_impulse.x(), -kFriction * rig.row().normal_impulse,
              1e-9 * rig.row().normal_impulse);
  EXPECT_GT(rig.point().x(), x + 0.004);
  EXPECT_NEAR(rig.point().y(), kMargin, 1e-12);
}

TEST(BodyStop, ARowNamingAMissingBodyIsReported) {
  Rig rig;
  rig.gather();
  rig.state.body_stops[0].body = 3;
  prepare_state(rig.model, rig.state);
  EXPECT_NE(validate_state(rig.model, rig.state).find("surface stop"), std::string::npos);
}

}  // namespace
}  // namespace imasim::physics
