// The thorax scene's vessel solved by the implicit step of its own rows' energy
// (scene/implicit_mesh_scene.hpp, `vessel.solver = "implicit"`, the default): its rows leave
// XPBD, the heart's drive still reaches it through eq. 9's decay (here the spring whose
// backward-Euler step is that decay), and the fat an instrument holds pulls it (eq. 9, beta = 1)
// and lets it go back to rest. The press that this solver is for is in press_test.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "physics/executor.hpp"
#include "physics/implicit_membrane.hpp"
#include "scene/thorax_scene.hpp"
#include "tissue/coupling.hpp"
#include "tissue/mesh_object.hpp"

namespace imasim::scene {
namespace {

// Eq. 9's decay (0.8 a step) as a spring: a lone vertex at rest, 1 mm from its reference, comes
// to 0.8 mm in one implicit step, and to 0.8^n mm in n.
TEST(ImplicitVesselScene, TheDecaysSpringStepsALoneVertexAsEqNineDoes) {
  const Real mass = Real(2e-5), h = Real(0.005);
  tissue::OffsetCoupling c;
  c.decay = Real(0.8);
  const Real k = tissue::decay_spring_stiffness(c, mass, h);
  EXPECT_NEAR(k, mass / (h * h) / 4, 1e-12);  // (1 - 0.8) / 0.8 of m / h^2
  physics::ImplicitMembrane lone({mass}, {0}, {}, h);
  std::vector<Vec3> x = {Vec3(0.001, 0, 0)}, v = {Vec3::Zero()};
  const physics::MembraneAttachment spring{0, Vec3::Zero(), physics::kNoMembraneBody, k};
  physics::ImplicitLoads loads;
  loads.attachments = {&spring, 1};
  ASSERT_TRUE(lone.step(x, v, loads, {}).ok);
  EXPECT_NEAR(x[0].x(), 0.0008, 1e-12);
  // The velocity the step leaves carries the next one on: the offset then falls faster than the
  // decay alone (0.8^2), as after eq. 9's after-step decay, whose move becomes velocity too.
  ASSERT_TRUE(lone.step(x, v, loads, {}).ok);
  EXPECT_LT(x[0].x(), 0.00064);
  EXPECT_GT(x[0].x(), 0.0);
}

// Its rows leave XPBD; over a beat it steps solved, with its masses given back, and it moves with
// the heart as the XPBD vessel does (in the example session 3.86 mm at most, against 4.10 mm for
// the XPBD vessel of 40 rings without its columns: the drive reaches it through eq. 9's decay;
// without the decay, the implicit vessel stayed still).
TEST(ImplicitVesselScene, TheVesselsRowsLeaveXpbdAndItMovesWithTheBeatingHeart) {
  double motion[2] = {0, 0};
  std::size_t xpbd_rows = 0;
  for (int implicit = 0; implicit < 2; ++implicit) {
    ThoraxSceneParams params = default_thorax_scene_params();
    params.vessel_solver = implicit ? kImplicitFasciaSolver : kXpbdFasciaSolver;
    ThoraxScene s = make_thorax_scene(params);
    ASSERT_EQ(s.implicit_vessel.has_value(), bool(implicit));
    tissue::TissueWorld& w = s.patch.world;
    const tissue::MeshObject& ima = w.meshes[s.patch.ima];
    const std::uint32_t first = ima.first_particle, end = first + ima.particle_count;
    auto of_vessel = [&](std::uint32_t p) { return p >= first && p < end; };
    std::size_t rows = 0;
    for (const auto& group : w.state.constraints.distance.groups())
      for (const physics::DistanceRow& r : group.rows)
        rows += of_vessel(r.i) || of_vessel(r.j);
    for (const auto& group : w.state.constraints.dihedral.groups())
      for (const physics::DihedralRow& r : group.rows)
        rows += std::any_of(r.p.begin(), r.p.end(), of_vessel);
    if (implicit) {
      // Every XPBD row of the vessel is a spring or a hinge of its implicit step.
      EXPECT_EQ(rows, 0u);
      const tissue::MeshRows& taken = s.implicit_vessel->rows;
      EXPECT_EQ(taken.edges.size() + taken.dihedrals.size(), xpbd_rows);
      EXPECT_EQ(s.implicit_vessel->solver.membrane->edges().size(), taken.edges.size());
    } else {
      xpbd_rows = rows;
      EXPECT_GT(rows, 5u * ima.particle_count);
    }
    const std::vector<Real> mass_before = w.state.particles.inverse_mass;
    const std::vector<Vec3> start = w.state.particles.position;
    physics::Executor exec(1);
    for (int n = 0; n < 200; ++n) {  // 1 s: a beat
      ASSERT_TRUE(step_thorax_scene(s, exec).ok()) << "step " << n;
      if (implicit) {
        ASSERT_TRUE(s.implicit_vessel->last.ok);
        EXPECT_LE(s.implicit_vessel->last.residual, s.implicit_vessel->solve.tolerance) << n;
      }
      for (std::uint32_t p = first; p < end; ++p)
        motion[implicit] =
            std::max(motion[implicit], double((w.state.particles.position[p] - start[p]).norm()));
    }
    EXPECT_EQ(w.state.particles.inverse_mass, mass_before);
  }
  EXPECT_GT(motion[0], 1e-3);
  EXPECT_NEAR(motion[1], motion[0], 0.25 * motion[0]);
}

// The fat beside the vessel's middle, grasped and drawn 8 mm into the cavity, takes the vessel
// with it (eq. 9, beta = 1: the vessel follows the held fat's offset, clamped to lambda_max,
// 10 mm); let go, the vessel comes back to rest where it was (eq. 9's decay, its rows, its
// columns). Returns how far the vessel moved at most, held and after.
struct Retraction {
  double held = 0, after = 0, speed_after = 0;
};

Retraction retract_the_fat_beside_the_vessel() {
  ThoraxSceneParams params = default_thorax_scene_params();
  params.playback.beating = false;
  ThoraxScene s = make_thorax_scene(params);
  tissue::TissueWorld& w = s.patch.world;
  physics::Executor exec(1);
  for (int n = 0; n < 100; ++n)
    EXPECT_TRUE(step_thorax_scene(s, exec).ok());
  const tissue::MeshObject& ima = w.meshes[s.patch.ima];
  const tissue::MeshObject& fascia = w.meshes[s.patch.fascia];
  physics::Particles& P = w.state.particles;
  const std::vector<Vec3> settled = P.position;
  // The vessel's middle, and the way into the cavity: towards the fascia over it.
  Vec3 middle = Vec3::Zero(), cover = Vec3::Zero();
  for (std::uint32_t k = 0; k < ima.particle_count; ++k)
    middle += P.position[ima.first_particle + k] / Real(ima.particle_count);
  for (std::uint32_t k = 0; k < fascia.particle_count; ++k)
    cover += P.position[fascia.first_particle + k] / Real(fascia.particle_count);
  const Vec3 inward = (cover - middle).normalized();
  const physics::MaterialId grip = w.model.add_material(physics::ConstraintMaterial::xpbd(0));
  std::vector<physics::AttachmentHandle> holds;
  const tissue::StrandSet& fat = w.strands[s.patch.ima_fat];
  for (std::uint32_t strand = 0; strand < fat.strand_count; ++strand) {
    const std::uint32_t i = fat.particle(strand, 1);
    if ((P.position[i] - middle).norm() > Real(0.006)) continue;
    holds.push_back(physics::add_attachment(w.state.constraints, P, i,
                                            settled[i] + Real(0.008) * inward, grip));
    w.held[i] = 1;
  }
  EXPECT_GT(holds.size(), 4u);
  physics::prepare_state(w.model, w.state);
  Retraction r;
  auto vessel_moved = [&] {
    double moved = 0;
    for (std::uint32_t k = 0; k < ima.particle_count; ++k) {
      const std::uint32_t i = ima.first_particle + k;
      moved = std::max(moved, double((P.position[i] - settled[i]).norm()));
    }
    return moved;
  };
  for (int n = 0; n < 200; ++n) {
    EXPECT_TRUE(step_thorax_scene(s, exec).ok());
    EXPECT_TRUE(s.implicit_vessel->last.ok);
  }
  r.held = vessel_moved();
  for (const physics::AttachmentHandle h : holds)
    w.state.constraints.attachment.remove(h);
  std::fill(w.held.begin(), w.held.end(), std::uint8_t(0));
  physics::prepare_state(w.model, w.state);
  for (int n = 0; n < 400; ++n)
    EXPECT_TRUE(step_thorax_scene(s, exec).ok());
  r.after = vessel_moved();
  for (std::uint32_t k = 0; k < ima.particle_count; ++k)
    r.speed_after = std::max(r.speed_after, double(P.velocity[ima.first_particle + k].norm()));
  return r;
}

TEST(ImplicitVesselScene, RetractingTheFatMovesTheVesselAndLetGoItComesToRest) {
  const Retraction r = retract_the_fat_beside_the_vessel();
  EXPECT_GT(r.held, 0.004);
  EXPECT_LE(r.held, 0.0101);  // lambda_max
  EXPECT_LT(r.after, 1e-4);
  EXPECT_LT(r.speed_after, 1e-4);
}

}  // namespace
}  // namespace imasim::scene
