// A particle held by a proxy body (physics/body_attachment.hpp): a weight hanging from the proxy
// sinks it until eq. 17's spring carries it, within its first step, and the attachment's impulse
// on the body over a step is the weight's.
#include <gtest/gtest.h>

#include "physics/executor.hpp"
#include "physics/step.hpp"
#include "physics/validation.hpp"

namespace imasim::physics {
namespace {

constexpr Real kStiffness = 100;    // k (unit: N/m), the vessel's k_d
constexpr Real kDamping = 1;        // c (unit: N s/m)
constexpr Real kCompliance = 1e-6;  // the grasp's alpha (unit: m/N)
constexpr Real kMass = 0.01, kGravity = 9.81;

struct Rig {
  Model model;
  State state;
  Executor exec{1};

  Rig() {
    ObjectParams object;
    object.gravity = Vec3(0, -kGravity, 0);
    model.objects.push_back(object);
    model.solver.substeps = 32;
    model.solver.iterations = 1;
    state.particles.add(Vec3::Zero(), kMass, 0);
    ProxyBody b;
    b.stiffness = kStiffness;
    b.damping = kDamping;
    state.proxies.push_back(b);
  }
  // The hold as the grasper writes it each step: the target on the jaws where the step begins.
  void run(int steps) {
    for (int n = 0; n < steps; ++n) {
      state.body_attachments.clear();
      state.body_attachments.push_back(
          {0, 0, body().offset, kCompliance, Vec3::Zero(), Vec3::Zero()});
      ASSERT_TRUE(step(model, state, exec).ok());
    }
  }
  ProxyBody& body() { return state.proxies[0]; }
};

TEST(BodyAttachment, TheWeightPullsTheProxyWithinItsFirstStep) {
  Rig rig;
  rig.run(1);
  // Not one step behind: the body has moved down and felt part of the weight already.
  EXPECT_LT(rig.body().offset.y(), 0);
  EXPECT_LT(rig.body().impulse.y(), 0);
  EXPECT_GT(rig.body().impulse.y(), -kMass * kGravity * rig.model.solver.dt);
}

TEST(BodyAttachment, AWeightHangingFromTheProxySinksItUntilTheSpringCarriesIt) {
  Rig rig;
  rig.run(400);
  const Real weight = kMass * kGravity, dt = rig.model.solver.dt;
  const Real sink = weight / kStiffness;  // 1 mm
  EXPECT_NEAR(rig.body().offset.y(), -sink, 1e-6 * sink);
  EXPECT_NEAR(rig.body().offset.x(), 0, 1e-15);
  EXPECT_NEAR(rig.body().impulse.y() / dt, -weight, 1e-6 * weight);
  EXPECT_EQ(held_pull_on_body(rig.state.body_attachments, 0, dt), rig.body().impulse / dt);
  EXPECT_NEAR(rig.state.particles.velocity[0].y(), 0, 1e-9);
  // The particle hangs below the jaws by the attachment's stretch, alpha m g, but for the
  // splitting of a substep (the spring lifts the body by m g h / c after the hold).
  const Real h = dt / Real(rig.model.solver.substeps);
  EXPECT_NEAR(rig.state.particles.position[0].y() - rig.body().offset.y(),
              -weight * (kCompliance + h / kDamping), 1e-3 * weight * kCompliance);
}

TEST(BodyAttachment, AKinematicParticleThatHoldsTheBodyKeepsItAtTheHold) {
  // A kinematic particle (the implicit fascia held still while the XPBD step runs): idle without
  // holds_body; with it, the body is drawn back to the hold, 2 mm against its spring, and the
  // particle stays.
  BodyAttachmentRow row{0, 0, Vec3(0, 0.002, 0), 0, Vec3::Zero(), Vec3::Zero()};
  ProxyBody body;
  body.stiffness = kStiffness;
  body.damping = kDamping;
  Vec3 x = Vec3::Zero();
  const Real w = 0, h = 1e-4;
  project_body_attachment(row, &x, &w, body, h);
  EXPECT_EQ(body.offset, Vec3::Zero());
  row.holds_body = true;
  project_body_attachment(row, &x, &w, body, h);
  EXPECT_EQ(x, Vec3::Zero());
  EXPECT_NEAR(body.offset.y(), -0.002, 1e-15);  // the target on the particle: rigid, all at once
  EXPECT_NEAR(row.impulse.y(), -kDamping * 0.002, 1e-15);
  EXPECT_EQ(body.impulse, row.impulse);
}

TEST(BodyAttachment, AHoldNamingAMissingParticleOrBodyIsReported) {
  Rig rig;
  rig.state.body_attachments.push_back(
      {5, 0, Vec3::Zero(), kCompliance, Vec3::Zero(), Vec3::Zero()});
  prepare_state(rig.model, rig.state);
  EXPECT_NE(validate_state(rig.model, rig.state).find("missing particle"), std::string::npos);
  rig.state.body_attachments[0] = {0, 2, Vec3::Zero(), kCompliance, Vec3::Zero(), Vec3::Zero()};
  EXPECT_NE(validate_state(rig.model, rig.state).find("missing proxy body"), std::string::npos);
}

}  // namespace
}  // namespace imasim::physics
