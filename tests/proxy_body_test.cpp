// The proxy as a body inside the solve (physics/proxy_body.hpp): its coupling relaxes by the
// implicit Euler factor of eq. 17's spring and damper, a weight resting on it sinks it to k o = m
// g, a heavy particle driven into it meets eq. 17's k o + c do/dt, and an inactive body is a
// kinematic surface to the last bit.
#include <gtest/gtest.h>

#include <cmath>

#include "physics/executor.hpp"
#include "physics/step.hpp"

namespace imasim::physics {
namespace {

constexpr Real kStiffness = 300;  // k (unit: N/m), the fascia's k_d
constexpr Real kDamping = 2;      // c (unit: N s/m), the fascia's c_d

struct Rig {
  Model model;
  State state;
  Executor exec{1};

  // One particle of `mass` at `at` (an object with `gravity`), 32 substeps of the 5 ms step, and
  // one proxy body with the fascia's coupling.
  Rig(Real mass, const Vec3& at, const Vec3& gravity) {
    ObjectParams object;
    object.gravity = gravity;
    model.objects.push_back(object);
    model.solver.substeps = 32;
    model.solver.iterations = 1;
    state.particles.add(at, mass, 0);
    ProxyBody b;
    b.stiffness = kStiffness;
    b.damping = kDamping;
    state.proxies.push_back(b);
  }

  // The body's surface: the plane y = 0 of its device path (still), normal +y, carried by the
  // offset the body had when the row was gathered, as an instrument's owner gathers it.
  void gather(std::uint32_t body = 0) {
    state.contacts.clear();
    ContactRow c;
    c.particle = 0;
    c.point0 = c.point1 = body == kNoBody ? Vec3::Zero() : state.proxies[0].offset;
    c.normal = Vec3::UnitY();
    c.body = body;
    state.contacts.rows.push_back(c);
  }

  void run(int steps, std::uint32_t body = 0) {
    for (int n = 0; n < steps; ++n) {
      gather(body);
      ASSERT_TRUE(step(model, state, exec).ok());
    }
  }
  ProxyBody& body() { return state.proxies[0]; }
  Real h() const { return model.solver.dt / Real(model.solver.substeps); }
};

TEST(ProxyBody, TheCouplingRelaxesByTheImplicitEulerFactorOfItsSpringAndDamper) {
  Rig rig(0.001, Vec3(0, 1, 0), Vec3::Zero());  // the particle far away: no contact
  rig.body().offset = Vec3(0, 0, 0.01);
  rig.body().rest = Vec3(0, 0, 0.002);
  rig.state.contacts.clear();
  ASSERT_TRUE(step(rig.model, rig.state, rig.exec).ok());
  // c do/dt = -k (o - o_rest), one implicit Euler step per substep: times c / (c + k h) each.
  const Real factor = std::pow(kDamping / (kDamping + kStiffness * rig.h()), 32);
  EXPECT_NEAR(rig.body().offset.z(), 0.002 + 0.008 * factor, 1e-15);
  // Near exp(-k dt / c), the continuous decay over the step: implicit Euler's relative error
  // is (k dt / c)(k h / c) / 2 to first order, 0.9 % here.
  const Real continuous = std::exp(-kStiffness * rig.model.solver.dt / kDamping);
  EXPECT_NEAR(factor / continuous - 1, 0.75 * (kStiffness * rig.h() / kDamping) / 2, 1e-4);
  EXPECT_EQ(rig.body().offset.x(), 0);
  // Bounded: a rest beyond max_offset leaves the offset on the bound.
  rig.body().rest = Vec3(0.1, 0, 0);
  for (int n = 0; n < 50; ++n)
    ASSERT_TRUE(step(rig.model, rig.state, rig.exec).ok());
  EXPECT_NEAR(rig.body().offset.norm(), rig.body().max_offset, 1e-15);
}

TEST(ProxyBody, AWeightRestingOnTheProxySinksItUntilTheSpringCarriesIt) {
  // 10 g on the plane under gravity: at rest k o = m g, and the contact's impulse over a step,
  // on the particle and on the body alike, is m g dt.
  const Real mass = 0.01, g = 9.81;
  Rig rig(mass, Vec3::Zero(), Vec3(0, -g, 0));
  rig.run(400);
  const Real sink = mass * g / kStiffness;  // 0.33 mm
  const Real dt = rig.model.solver.dt;
  EXPECT_NEAR(rig.body().offset.y(), -sink, 1e-6 * sink);
  EXPECT_NEAR(rig.body().offset.x(), 0, 1e-15);
  EXPECT_NEAR(rig.state.contacts.rows[0].normal_impulse / dt, mass * g, 1e-6 * mass * g);
  EXPECT_NEAR(rig.body().impulse.y() / dt, -mass * g, 1e-6 * mass * g);
  EXPECT_NEAR(rig.state.particles.velocity[0].y(), 0, 1e-9);
  // The particle rests on the proxy's surface but for the splitting of a substep: the contact
  // puts it on the surface, then the spring lifts the body by the impulse's share, m g h / c
  // (8 um) into it.
  EXPECT_NEAR(rig.state.particles.position[0].y(), -sink - mass * g * rig.h() / kDamping,
              1e-6 * sink);
}

TEST(ProxyBody, AHeavyParticleDrivenIntoTheProxyMeetsTheSpringAndTheDamper) {
  // 10 t moving at 10 mm/s along -y into the proxy (no gravity): it hardly slows, so the proxy
  // retreats with it at 10 mm/s and the contact carries eq. 17's k o + c v over the step, o the
  // offset's mean over it (v dt / 2 short of its end): the damper's 20 mN on the spring's.
  const Real v = 0.01;
  Rig rig(10000, Vec3(0, Real(0.0001), 0), Vec3::Zero());
  rig.state.particles.velocity[0] = Vec3(0, -v, 0);
  rig.run(60);  // 0.3 s: the proxy 2.9 mm down
  const Real dt = rig.model.solver.dt;
  const Real o = -rig.body().offset.y() - v * dt / 2;
  EXPECT_GT(o, 0.0025);
  EXPECT_NEAR(-rig.state.particles.velocity[0].y(), v, 2e-3 * v);  // slowed 0.13 %
  const Real force = rig.state.contacts.rows[0].normal_impulse / dt;
  EXPECT_NEAR(force, kStiffness * o + kDamping * v, 0.02 * kDamping * v);
  EXPECT_NEAR(-rig.body().impulse.y() / dt, force, 1e-9);
}

TEST(ProxyBody, AnInactiveBodyIsAKinematicSurface) {
  // A row naming a body with no coupling (stiffness 0) moves its particle exactly as a row naming
  // none, and the body stays where it was.
  Rig with(0.001, Vec3(0, Real(0.0005), 0), Vec3(0, -9.81, 0));
  Rig without(0.001, Vec3(0, Real(0.0005), 0), Vec3(0, -9.81, 0));
  with.body().stiffness = 0;
  with.run(50);
  without.run(50, kNoBody);
  EXPECT_EQ(with.state.particles.position[0], without.state.particles.position[0]);
  EXPECT_EQ(with.state.particles.velocity[0], without.state.particles.velocity[0]);
  EXPECT_EQ(with.body().offset, Vec3::Zero());
}

TEST(ProxyBody, ADivergedOrNonFiniteBodyGoesBackToWhereItsStepBegan) {
  Rig rig(0.001, Vec3(0, 1, 0), Vec3::Zero());
  rig.body().offset = Vec3(NAN, 0, 0);
  rig.state.contacts.clear();
  ProxyBody& b = rig.body();
  keep_proxy_finite(b);
  EXPECT_EQ(b.offset, Vec3::Zero());
  b.offset = Vec3(0, 0, 0.001);
  b.step_start = Vec3(0, 0, 0.001);
  b.offset.x() = INFINITY;
  keep_proxy_finite(b);
  EXPECT_EQ(b.offset, Vec3(0, 0, 0.001));
}

}  // namespace
}  // namespace imasim::physics
