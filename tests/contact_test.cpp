// Contacts inside the solve (physics/contact.hpp): a particle on a moving surface.
#include <gtest/gtest.h>

#include <utility>

#include "physics/contact.hpp"
#include "physics/executor.hpp"
#include "physics/step.hpp"

namespace imasim::physics {
namespace {

struct Slab {
  Model model;
  State state;
};

// A 1 g particle resting on the plane y = 0 (gravity -y presses it on); the plane slides along x
// at `speed` during the step (point0 -> point1), with friction mu_s, mu_k.
Slab particle_on_a_sliding_plane(Real speed, Real mu_s, Real mu_k, std::uint32_t substeps) {
  Slab s;
  s.model.objects.push_back(ObjectParams{});
  s.model.solver.substeps = substeps;
  s.model.solver.iterations = 1;
  s.state.particles.add(Vec3::Zero(), 0.001, 0);
  ContactRow c;
  c.particle = 0;
  c.point0 = Vec3::Zero();
  c.point1 = Vec3(speed * s.model.solver.dt, 0, 0);
  c.normal = Vec3::UnitY();
  c.static_friction = mu_s;
  c.kinetic_friction = mu_k;
  s.state.contacts.rows.push_back(c);
  return s;
}

// Static friction carries the particle with the moving surface: within one step (the needed
// acceleration, 2 m/s^2, is below mu_s g) its velocity becomes the surface's, relative velocity
// zero, not zero as a world-frame rule would leave it.
TEST(Contact, StaticFrictionCarriesTheParticleWithTheMovingSurface) {
  Slab s = particle_on_a_sliding_plane(0.01, 1.0, 0.8, 1);
  Executor exec(1);
  ASSERT_TRUE(step(s.model, s.state, exec).ok());
  EXPECT_NEAR(s.state.particles.position[0].x(), 0.01 * 0.005, 1e-12);
  EXPECT_NEAR(s.state.particles.velocity[0].x(), 0.01, 1e-9);
  EXPECT_NEAR(s.state.particles.position[0].y(), 0, 1e-15);  // held on the surface
  EXPECT_GT(s.state.contacts.rows[0].depth, 0);
  // The normal impulse over the step carries the weight: m g dt.
  EXPECT_NEAR(s.state.contacts.rows[0].normal_impulse, 0.001 * 9.81 * 0.005, 1e-9);
}

// With 8 substeps the surface's jump per substep needs more than mu_s g: the particle slips at
// first (kinetic), then sticks and moves with the surface; the contact is re-gathered each step
// as its owner does, the plane advancing with the surface.
TEST(Contact, FrictionBringsTheParticleToTheSurfacesVelocityAcrossSubsteps) {
  Slab s = particle_on_a_sliding_plane(0.01, 1.0, 0.8, 8);
  Executor exec(1);
  for (int n = 0; n < 10; ++n) {
    ContactRow& c = s.state.contacts.rows[0];
    c.point0 = Vec3(0.01 * 0.005 * n, 0, 0);
    c.point1 = Vec3(0.01 * 0.005 * (n + 1), 0, 0);
    ASSERT_TRUE(step(s.model, s.state, exec).ok());
  }
  EXPECT_NEAR(s.state.particles.velocity[0].x(), 0.01, 1e-9);
  EXPECT_NEAR(s.state.particles.position[0].y(), 0, 1e-15);
}

// Without friction the surface slides under the particle, which stays where it was.
TEST(Contact, AFrictionlessSurfaceSlidesUnderTheParticle) {
  Slab s = particle_on_a_sliding_plane(0.01, 0, 0, 4);
  Executor exec(1);
  ASSERT_TRUE(step(s.model, s.state, exec).ok());
  EXPECT_NEAR(s.state.particles.position[0].x(), 0, 1e-15);
  EXPECT_NEAR(s.state.particles.velocity[0].x(), 0, 1e-12);
}

// Kinetic friction: the slip exceeds mu_s times the normal correction, and is reduced by mu_k
// times it each substep, the Coulomb bound mu_k g per unit mass on the acceleration.
TEST(Contact, KineticFrictionAcceleratesByAtMostMuKG) {
  const Real mu_k = 0.2;
  Slab s = particle_on_a_sliding_plane(1.0, 0.25, mu_k, 1);
  Executor exec(1);
  ASSERT_TRUE(step(s.model, s.state, exec).ok());
  // One substep of 5 ms: normal correction g h^2, slip reduced by mu_k g h^2.
  EXPECT_NEAR(s.state.particles.velocity[0].x(), mu_k * 9.81 * 0.005, 1e-9);
}

// A penetration found at a step's start is resolved in position only: the particle ends on the
// surface at rest, whatever the substep count. (Before the velocity pass it left at D / h: 0.2
// m/s at 8 substeps, 12.8 m/s at 512.)
TEST(Contact, ResolvingAPenetrationDoesNotLaunchTheParticle) {
  for (std::uint32_t substeps : {1u, 8u, 64u, 512u}) {
    Slab s = particle_on_a_sliding_plane(0, 0.3, 0.2, substeps);
    s.model.objects[0].gravity = Vec3::Zero();
    s.state.particles.position[0] = Vec3(0, -0.001, 0);  // 1 mm inside
    Executor exec(1);
    ASSERT_TRUE(step(s.model, s.state, exec).ok());
    EXPECT_NEAR(s.state.particles.position[0].y(), 0, 1e-15) << substeps << " substeps";
    EXPECT_EQ(s.state.particles.velocity[0].y(), 0) << substeps << " substeps";
    ASSERT_TRUE(step(s.model, s.state, exec).ok());
    EXPECT_NEAR(s.state.particles.position[0].y(), 0, 1e-15) << substeps << " substeps";
  }
}

// An overlap found at a step's start is pushed out at SolverParams::push_out_speed, whatever the
// substep count: 2 mm inside at 0.1 m/s is 1.5 mm inside after a 5 ms step, 1 mm after two, at
// rest (the velocity pass), and out after four. Resolved in one substep, it would set the
// particle's neighbours moving at D / h (docs/physics.md). The overlap allowance is the part of
// the starting depth not yet pushed out.
TEST(Contact, AnOverlapFoundAtAStepsStartIsPushedOutAtThePushOutSpeed) {
  ContactRow c;
  c.start_depth = 0.002;
  EXPECT_DOUBLE_EQ(overlap_allowance(c, 0.0005), 0.0015);
  EXPECT_EQ(overlap_allowance(c, 0.003), 0);
  for (std::uint32_t substeps : {1u, 8u, 64u, 512u}) {
    Slab s = particle_on_a_sliding_plane(0, 0.3, 0.2, substeps);
    s.model.objects[0].gravity = Vec3::Zero();
    s.model.solver.push_out_speed = 0.1;
    s.state.particles.position[0] = Vec3(0, -0.002, 0);
    Executor exec(1);
    for (const Real inside : {0.0015, 0.001, 0.0005, 0.0}) {
      ASSERT_TRUE(step(s.model, s.state, exec).ok());
      EXPECT_NEAR(s.state.particles.position[0].y(), -inside, 1e-12) << substeps << " substeps";
      EXPECT_EQ(s.state.particles.velocity[0].y(), 0) << substeps << " substeps";
    }
  }
}

// Penetration that arises within the step is not an overlap found at its start: a surface
// moving out into a particle resting on it pushes it at once (the next test), however slow the
// push-out speed.
TEST(Contact, APushingSurfaceIsNotSlowedByThePushOutSpeed) {
  Slab s = particle_on_a_sliding_plane(0, 0, 0, 16);
  s.model.objects[0].gravity = Vec3::Zero();
  s.model.solver.push_out_speed = 1e-4;
  s.state.contacts.rows[0].point1 = Vec3(0, 0.1 * s.model.solver.dt, 0);
  Executor exec(1);
  ASSERT_TRUE(step(s.model, s.state, exec).ok());
  EXPECT_NEAR(s.state.particles.position[0].y(), 0.1 * s.model.solver.dt, 1e-15);
}

// The pass removes only separation relative to the surface: a particle pushed by a surface
// moving out at 0.1 m/s (an instrument pressing tissue) leaves with the surface's velocity.
TEST(Contact, APushingSurfaceGivesItsOwnNormalVelocity) {
  Slab s = particle_on_a_sliding_plane(0, 0, 0, 16);
  s.model.objects[0].gravity = Vec3::Zero();
  s.state.contacts.rows[0].point1 = Vec3(0, 0.1 * s.model.solver.dt, 0);
  Executor exec(1);
  ASSERT_TRUE(step(s.model, s.state, exec).ok());
  EXPECT_NEAR(s.state.particles.position[0].y(), 0.1 * s.model.solver.dt, 1e-15);
  EXPECT_NEAR(s.state.particles.velocity[0].y(), 0.1, 1e-12);
}

// A row on the plane y = 0 through the origin, at rest, with friction mu_s, mu_k.
ContactRow row_on_plane(Real mu_s, Real mu_k) {
  ContactRow c;
  c.normal = Vec3::UnitY();
  c.static_friction = mu_s;
  c.kinetic_friction = mu_k;
  return c;
}

// Two projections of row c in one substep of a particle that started at the origin: the first
// of `predicted`, the second after a sweep moved the particle by `sweep`. Returns where each
// left it.
std::pair<Vec3, Vec3> project_twice(ContactRow& c, const Vec3& predicted, const Vec3& sweep) {
  const Vec3 x_start = Vec3::Zero();
  const Real w = 1000, h = 1e-4;
  Vec3 x = predicted;
  project_contact(c, &x, &x_start, &w, 0, 1, h);
  const Vec3 first = x;
  x += sweep;
  project_contact(c, &x, &x_start, &w, 0, 1, h);
  return {first, x};
}

// Coulomb's bound holds over the substep, not per projection: a row projected twice in a substep
// (the second stretch sweep) keeps static friction when the second projection's own normal
// correction is small. Here the first projection pushes the particle 1 mm out and holds its
// 0.1 mm slip (0.1 mm < mu_s 1 mm); a sweep then moves it back 0.1 mm along the plane and 1 um
// into it. Against that 1 um alone the particle would slip (0.1 mm > 0.5 um) and keep 99.6 % of
// it; against the substep's 1.001 mm it is held where the surface is.
TEST(Contact, StaticFrictionHoldsAcrossASecondProjectionInTheSubstep) {
  ContactRow c = row_on_plane(0.5, 0.4);
  const auto [first, second] = project_twice(c, Vec3(1e-4, -1e-3, 0), Vec3(1e-4, -1e-6, 0));
  EXPECT_NEAR(first.norm(), 0, 1e-15);
  EXPECT_NEAR(second.norm(), 0, 1e-15);
  EXPECT_NEAR(c.substep_normal, 1.001e-3, 1e-15);
}

// Sliding, the friction over the substep is mu_k times its push, not more and not more than once:
// the first projection is static (it holds 0.4 mm of slip, within mu_s 1 mm), and a sweep then
// drags the particle 1 mm along the plane, 1 nm into it. The friction wanted, 1.4 mm, is beyond
// mu_s; it is put on mu_k's rim, 0.3000003 mm, so the particle gets back the 0.0999997 mm it was
// held beyond that and slides 1.0999997 mm. Per projection, friction would have taken another
// mu_k 1 nm from the drag and kept the 0.4 mm.
TEST(Contact, KineticFrictionOverTheSubstepIsMuKTimesItsPush) {
  ContactRow c = row_on_plane(0.5, 0.3);
  const auto [first, second] = project_twice(c, Vec3(4e-4, -1e-3, 0), Vec3(1e-3, -1e-9, 0));
  EXPECT_NEAR(first.x(), 0, 1e-15);
  EXPECT_NEAR(second.x(), 1e-3 + (4e-4 - 0.3 * 1.000001e-3), 1e-15);
  EXPECT_NEAR(c.substep_friction.x(), 0.3 * c.substep_normal, 1e-15);
}

// Static friction holds no more in all than mu_s times the substep's normal correction: the first
// projection pushes the particle 1 mm out and holds its 0.4 mm slip (within mu_s 1 mm = 0.5 mm);
// a sweep then moves it another 0.4 mm along the plane and 1 nm into it. Holding that too would
// take 0.8 mm of friction against 1.000001 mm of push, 1.6 mu_s; the row gives way instead and
// friction takes only what is left of the bound, 0.1000005 mm.
TEST(Contact, StaticFrictionHoldsNoMoreThanTheSubstepsBound) {
  ContactRow c = row_on_plane(0.5, 0.5);
  const auto [first, second] = project_twice(c, Vec3(4e-4, -1e-3, 0), Vec3(4e-4, -1e-9, 0));
  EXPECT_NEAR(first.x(), 0, 1e-15);
  EXPECT_NEAR(c.substep_friction.norm(), 0.5 * c.substep_normal, 1e-15);
  EXPECT_NEAR(second.x(), 4e-4 - (0.5 * 1.000001e-3 - 4e-4), 1e-15);
}

// Friction is a vector over the substep: a sweep that moves the particle back 0.3 mm against the
// 0.4 mm slip held so far leaves 0.1 mm of friction in all, well inside the bound, so the row
// holds it where the surface is. Adding the sizes (0.7 mm against 0.5 mm) would have let it slide.
TEST(Contact, FrictionGivenBackWithinTheSubstepStaysStatic) {
  ContactRow c = row_on_plane(0.5, 0.5);
  const auto [first, second] = project_twice(c, Vec3(4e-4, -1e-3, 0), Vec3(-3e-4, -1e-9, 0));
  EXPECT_NEAR(first.x(), 0, 1e-15);
  EXPECT_NEAR(second.x(), 0, 1e-15);
  EXPECT_NEAR(c.substep_friction.x(), 1e-4, 1e-15);
}

// The same bound against a proxy body's surface (the two-body overload): the second projection
// still holds the particle, now relative to the body, which takes its share of each correction.
TEST(Contact, StaticFrictionAgainstAProxyBodyHoldsAcrossASecondProjection) {
  ContactRow c = row_on_plane(0.5, 0.4);
  ProxyBody body;
  body.stiffness = 500;
  body.damping = 2;
  const Vec3 x_start = Vec3::Zero();
  const Real h = 1e-4;
  const Real w = 1 / (body.damping * h);  // as light as the body: each takes half
  Vec3 x(1e-4, -1e-3, 0);
  project_contact(c, &x, &x_start, &w, body, Vec3::Zero(), 0, 1, h);
  const Vec3 slip_after_first = x - body.offset;
  EXPECT_NEAR(slip_after_first.x(), 0, 1e-15);
  x += Vec3(1e-4, -1e-6, 0);
  const Vec3 body_before = body.offset;
  project_contact(c, &x, &x_start, &w, body, Vec3::Zero(), 0, 1, h);
  EXPECT_NEAR((x - body.offset).x(), 0, 1e-15);   // held: no tangential slip relative to the body
  EXPECT_GT((body.offset - body_before).x(), 0);  // and the body was dragged its share
}

// A kinematic particle (the implicit fascia while the XPBD step runs, held still there) is an
// obstacle for a proxy body when its row says so: the body takes the whole correction and the
// particle stays; without the flag the row is idle, as for any kinematic particle.
TEST(Contact, AKinematicParticleThatStopsTheBodyPushesItOutWhole) {
  ContactRow c = row_on_plane(0, 0);
  c.body = 0;
  ProxyBody body;
  body.stiffness = 500;
  body.damping = 2;
  const Vec3 x_start = Vec3::Zero();
  const Real h = 1e-4, w = 0;
  Vec3 x(0, -1e-3, 0);  // 1 mm inside the tool's surface
  project_contact(c, &x, &x_start, &w, body, Vec3::Zero(), 0, 1, h);
  EXPECT_EQ(body.offset, Vec3::Zero());  // idle
  c.stops_body = true;
  project_contact(c, &x, &x_start, &w, body, Vec3::Zero(), 0, 1, h);
  EXPECT_EQ(x, Vec3(0, -1e-3, 0));
  EXPECT_NEAR(body.offset.y(), -1e-3, 1e-15);  // the surface moved out by the whole gap
  EXPECT_NEAR(body.impulse.y(), -body.damping * 1e-3, 1e-15);
  EXPECT_NEAR(c.depth, 1e-3, 1e-15);
  const Vec3 after = body.offset;
  project_contact(c, &x, &x_start, &w, body, Vec3::Zero(), 0, 1, h);
  EXPECT_EQ(body.offset, after);  // touching, not inside: nothing more
}

}  // namespace
}  // namespace imasim::physics
