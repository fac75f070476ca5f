// The world's fascia solved by the implicit membrane step (tissue/implicit_fascia.hpp): built
// from the mesh object as it is (fixed perimeter, eq. 5's masses), one step moves only the free
// particles and gives them the step's velocity, and the fascia's law (2.65 MPa past 5 % strain)
// sags between its toe's modulus throughout and its linear modulus throughout. The rest against
// converged XPBD is in convergence_test.cpp (label physics).
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "tissue/implicit_fascia.hpp"
#include "tissue/mesh_object.hpp"
#include "tissue/thoracic_patch.hpp"
#include "tissue/tissue_step.hpp"

namespace imasim::tissue {
namespace {

const Vec3 kGravity(0, -9.81, 0);
const physics::Executor kSerial(1);

struct FasciaWorld {
  TissueWorld world;
  std::uint32_t mesh = 0;
};

FasciaWorld fascia_world() {
  FasciaWorld f;
  f.world.model.solver = default_solver();
  f.mesh = add_fascia(f.world, default_fascia_params());
  finish_setup(f.world);
  return f;
}

// The toe's modulus (the scene's fascia, 0.1 MPa) unless given, stiffening to linear_modulus past
// 5 % strain.
physics::StiffeningMembrane fascia_law(Real linear_modulus, Real toe_modulus = 0) {
  const physics::MembraneMaterial m = default_fascia_membrane();
  return {toe_modulus > 0 ? toe_modulus : m.youngs_modulus, linear_modulus, Real(0.05), m.thickness,
          Real(1100)};
}

TEST(ImplicitFascia, OneStepMovesTheFreeParticlesOnlyAndGivesThemTheStepsVelocity) {
  FasciaWorld f = fascia_world();
  const MeshObject& mesh = f.world.meshes[f.mesh];
  const physics::Particles& particles = f.world.state.particles;
  const Real h = f.world.model.solver.dt;
  ImplicitFascia fascia =
      make_implicit_fascia(f.world, f.mesh, fascia_law(Real(2.65e6)),
                           default_fascia_membrane().effective_bending_stiffness(), h);
  std::size_t free = 0;
  for (std::uint32_t k = 0; k < mesh.particle_count; ++k)
    free += particles.inverse_mass[mesh.first_particle + k] > 0;
  EXPECT_EQ(fascia.membrane->free_count(), free);
  EXPECT_GT(free, 300u);
  const std::vector<Vec3> before = particles.position;
  const physics::ImplicitStepReport report =
      step_implicit_fascia(fascia, f.world, kSerial, kGravity, {}, {}, {});
  ASSERT_TRUE(report.ok);
  EXPECT_LE(report.residual, physics::ImplicitSolveParams{}.tolerance);
  std::size_t moved = 0;
  for (std::uint32_t p = 0; p < particles.position.size(); ++p) {
    const bool in_fascia =
        p >= mesh.first_particle && p < mesh.first_particle + mesh.particle_count;
    if (!in_fascia || particles.inverse_mass[p] == 0) {
      EXPECT_EQ(particles.position[p], before[p]) << "particle " << p;
      continue;
    }
    EXPECT_LT(particles.position[p].y(), before[p].y()) << "particle " << p;
    EXPECT_NEAR((particles.velocity[p] - (particles.position[p] - before[p]) / h).norm(), 0, 1e-12);
    ++moved;
  }
  EXPECT_EQ(moved, free);
}

// The elements' forces are evaluated on the executor's threads and gathered per row in element
// order: the steps are the same to the bit on one thread and on two, a cut edge and hinge too.
TEST(ImplicitFascia, TheStepIsTheSameToTheBitOnOneThreadAndOnTwo) {
  const physics::Executor two(2);
  std::vector<Vec3> positions[2];
  for (int run = 0; run < 2; ++run) {
    FasciaWorld f = fascia_world();
    ImplicitFascia fascia = make_implicit_fascia(
        f.world, f.mesh, fascia_law(Real(2.65e6)),
        default_fascia_membrane().effective_bending_stiffness(), f.world.model.solver.dt);
    fascia.membrane->remove_edge(7);
    fascia.membrane->remove_hinge(3);
    for (int step = 0; step < 20; ++step)
      ASSERT_TRUE(
          step_implicit_fascia(fascia, f.world, run == 0 ? kSerial : two, kGravity, {}, {}, {}).ok);
    positions[run] = f.world.state.particles.position;
  }
  ASSERT_EQ(positions[0].size(), positions[1].size());
  std::size_t differ = 0;
  for (std::size_t p = 0; p < positions[0].size(); ++p)
    differ += positions[0][p] != positions[1][p];
  EXPECT_EQ(differ, 0u);
}

// Sag at rest after 1.5 s (unit: m).
double implicit_sag(Real linear_modulus, Real toe_modulus = 0) {
  FasciaWorld f = fascia_world();
  ImplicitFascia fascia = make_implicit_fascia(
      f.world, f.mesh, fascia_law(linear_modulus, toe_modulus),
      default_fascia_membrane().effective_bending_stiffness(), f.world.model.solver.dt);
  for (int step = 0; step < 300; ++step) {
    const physics::ImplicitStepReport report =
        step_implicit_fascia(fascia, f.world, kSerial, kGravity, {}, {}, {});
    EXPECT_TRUE(report.ok);
    EXPECT_LE(report.residual, physics::ImplicitSolveParams{}.tolerance) << "step " << step;
  }
  return max_displacement(f.world, f.world.meshes[f.mesh]);
}

// Under its own weight the sheet stretches about 0.5 %, inside the toe: the law's stiffness there
// lies between the toe's and the linear region's, and so does its sag (2.02 mm with the toe's
// modulus throughout, 1.87 with the law).
TEST(ImplicitFascia, TheFasciasLawSagsBetweenItsToeAndItsLinearModulusThroughout) {
  const Real toe = default_fascia_membrane().youngs_modulus, linear = Real(2.65e6);
  const double soft = implicit_sag(toe), law = implicit_sag(linear),
               stiff = implicit_sag(linear, linear);
  EXPECT_GT(soft, 0.5e-3);
  EXPECT_LT(law, 0.95 * soft);
  EXPECT_GT(law, stiff);
}

TEST(ImplicitFascia, RefusesAMeshOutOfRange) {
  FasciaWorld f = fascia_world();
  try {
    make_implicit_fascia(f.world, 7, fascia_law(Real(2.65e6)), Real(1e-5), Real(0.005));
    FAIL() << "accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("implicit fascia: mesh 7 of 1"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace imasim::tissue
