// Grasping: closing the forceps on the fascia catches the particles between the jaws; lifting
// the tool lifts the fascia and, through the coupling, the fat under it; opening releases it.
#include "surgery/grasp.hpp"

#include <gtest/gtest.h>

#include "physics/executor.hpp"
#include "tissue/thoracic_patch.hpp"
#include "tissue/tissue_step.hpp"

namespace imasim::surgery {
namespace {

// Mean y displacement from `before` of the fat strand particles whose rest position lies
// within `radius` of (x, z).
Real fat_lift(const tissue::ThoracicPatch& patch, const std::vector<Vec3>& before, Real x, Real z,
              Real radius) {
  const tissue::TissueWorld& w = patch.world;
  const tissue::StrandSet& fat = w.strands[patch.fascia_fat];
  const physics::Particles& P = w.state.particles;
  Real sum = 0;
  int count = 0;
  for (std::uint32_t s = 0; s < fat.strand_count; ++s) {
    for (std::uint32_t k = 1; k < fat.segments; ++k) {
      const std::uint32_t i = fat.particle(s, k);
      const Vec3& r = P.rest_position[i];
      if (std::hypot(r.x() - x, r.z() - z) > radius) continue;
      sum += P.position[i].y() - before[i].y();
      ++count;
    }
  }
  return count ? sum / count : 0;
}

TEST(Grasp, ForcepsLiftTheFasciaAndTheFatUnderItThenRelease) {
  tissue::ThoracicPatch patch =
      tissue::make_thoracic_patch(tissue::default_thoracic_patch_params());
  tissue::TissueWorld& w = patch.world;
  physics::Executor exec(1);
  const GraspParams params;
  Grasper grasper = make_grasper(w, params);
  tissue::finish_setup(w);
  InstrumentParams forceps;
  InstrumentState state;
  // Jaws open, away from the tissue while it settles under gravity (the fascia sags ~6 mm).
  state.controller.translation = Vec3(0, -0.05, 0.07);
  state.jaw_angle = forceps.jaws.max_angle;
  state.closed = false;
  const Real dt = w.model.solver.dt;
  for (int n = 0; n < 80; ++n) {
    EXPECT_EQ(update_grasp(w, params, forceps, state, grasper), 0u);
    ASSERT_TRUE(tissue::step_tissue(w, exec).ok());
  }
  // Then laid on the fascia along the vessel, opening towards the wall: at the fascia's height
  // where the jaws will close.
  const tissue::MeshObject& fascia = w.meshes[patch.fascia];
  Real fascia_y = 0;
  int under = 0;
  for (std::uint32_t k = 0; k < fascia.particle_count; ++k) {
    const Vec3& x = w.state.particles.position[fascia.first_particle + k];
    if (std::abs(x.x()) < 0.003 && x.z() > 0.07 && x.z() < 0.082) fascia_y += x.y(), ++under;
  }
  ASSERT_GT(under, 0);
  state.controller.translation.y() = fascia_y / under;
  const std::vector<Vec3> settled = w.state.particles.position;
  while (!state.closed) {
    integrate_jaws(forceps.jaws, JawCommand::close, dt, state);
    update_grasp(w, params, forceps, state, grasper);
    ASSERT_TRUE(tissue::step_tissue(w, exec).ok());
  }
  const std::size_t held = grasper.held.size();
  ASSERT_GE(held, 4u);  // two columns of the fascia's grid, a few rows
  for (const Grasper::Hold& h : grasper.held) {
    EXPECT_GE(h.particle, fascia.first_particle);
    EXPECT_LT(h.particle, fascia.first_particle + fascia.particle_count);
  }
  EXPECT_EQ(w.state.constraints.attachment.size(), held);

  // Retract 8 mm into the cavity over 0.4 s, then hold 0.2 s.
  const Real rest_pull =
      grasp_force_on_jaws(w.state.particles, params, world_pose(forceps, state), grasper).norm();
  Vec3 half_way_pull = Vec3::Zero();
  for (int n = 0; n < 120; ++n) {
    if (n < 80) state.controller.translation.y() -= 0.0001;
    update_grasp(w, params, forceps, state, grasper);
    ASSERT_TRUE(tissue::step_tissue(w, exec).ok());
    if (n == 39)
      half_way_pull =
          grasp_force_on_jaws(w.state.particles, params, world_pose(forceps, state), grasper);
  }
  const physics::Particles& P = w.state.particles;
  const Pose tool = world_pose(forceps, state);
  // The stretched fascia pulls the jaws back towards the wall (+y), harder the further it is
  // retracted; what it pulled with before the retraction is small beside it.
  const Vec3 pull = grasp_force_on_jaws(P, params, tool, grasper);
  EXPECT_GT(pull.y(), 0.5 * pull.norm());
  EXPECT_GT(pull.y(), 1.5 * half_way_pull.y());
  EXPECT_GT(half_way_pull.y(), 0);
  EXPECT_LT(rest_pull, 0.2 * pull.norm());
  for (const Grasper::Hold& h : grasper.held)
    EXPECT_LT((P.position[h.particle] - tool.apply(h.local)).norm(), 5e-4);
  const Real lifted = fat_lift(patch, settled, 0, 0.076, 0.004);
  EXPECT_LT(lifted, -0.002);  // the fat under the grasp follows the fascia into the cavity
  // The lift is local: fat 45 mm along the vessel moves less than half as far.
  EXPECT_LT(lifted, 2 * fat_lift(patch, settled, 0, 0.03, 0.004));

  // Open: released; the fascia springs back towards the wall.
  while (state.closed) {
    integrate_jaws(forceps.jaws, JawCommand::open, dt, state);
    update_grasp(w, params, forceps, state, grasper);
    ASSERT_TRUE(tissue::step_tissue(w, exec).ok());
  }
  EXPECT_TRUE(grasper.held.empty());
  EXPECT_EQ(w.state.constraints.attachment.size(), 0u);
  EXPECT_EQ(grasp_force_on_jaws(P, params, world_pose(forceps, state), grasper), Vec3::Zero());
  for (int n = 0; n < 200; ++n) {
    update_grasp(w, params, forceps, state, grasper);
    ASSERT_TRUE(tissue::step_tissue(w, exec).ok());
  }
  EXPECT_GT(fat_lift(patch, settled, 0, 0.076, 0.004),
            0.5 * lifted);  // less than half the lift remains
}

// Each hold is a spring of the grasp's compliance: the jaws get sum (x - target) / alpha.
TEST(Grasp, PullOnTheJawsIsTheHoldsStretchOverTheirCompliance) {
  physics::Particles P;
  P.add(Vec3(0.010, 0.001, 0.020), 1e-4, 0);
  P.add(Vec3(-0.002, 0.0, 0.015), 1e-4, 0);
  GraspParams params;
  params.compliance = 2e-6;  // (unit: m/N)
  Grasper g;
  g.held.push_back({0, {}, Vec3(0.010, 0.0, 0.020)});    // 1 mm off in y
  g.held.push_back({1, {}, Vec3(-0.002, 0.0, 0.0145)});  // 0.5 mm off in z
  Pose jaws;
  jaws.translation = Vec3(0, -0.0005, 0);  // the targets ride 0.5 mm lower
  const Vec3 f = grasp_force_on_jaws(P, params, jaws, g);
  EXPECT_NEAR(f.x(), 0, 1e-9);
  EXPECT_NEAR(f.y(), (0.0015 + 0.0005) / 2e-6, 1e-6);  // 1000 N
  EXPECT_NEAR(f.z(), 0.0005 / 2e-6, 1e-6);             // 250 N
  params.compliance = 0;                               // rigid holds: no force to read
  EXPECT_EQ(grasp_force_on_jaws(P, params, jaws, g), Vec3::Zero());
}

}  // namespace
}  // namespace imasim::surgery
