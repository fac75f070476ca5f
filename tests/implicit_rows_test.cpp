// A mesh object's own XPBD rows as an implicit membrane (tissue/implicit_rows.hpp): the vessel's
// tube, curved at rest, held at both ends and made heavy enough to sag measurably, rests where
// its XPBD rows converge to, solved in one Newton step (measured 5.37995 against 5.38005 mm, 2e-5
// apart; with the dihedrals twice as stiff, 1.4e-3 apart). The tube is heavy so that XPBD itself
// is converged at the default solve (its stiff rows' w h^2, 3e-5 m/N a row, far below their
// compliance, about 6e-3 m/N): the two solvers then minimise the same energy.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "physics/executor.hpp"
#include "tissue/implicit_rows.hpp"
#include "tissue/thoracic_patch.hpp"
#include "tissue/tissue_step.hpp"
#include "tissue/vessel.hpp"

namespace imasim::tissue {
namespace {

constexpr std::uint32_t kSegments = 6, kRings = 9;

struct TubeWorld {
  TissueWorld world;
  std::uint32_t mesh = 0;
};

// 30 mm of the vessel's wall (6 x 9), 0.1 kg, its end rings fixed: its middle sags 5.4 mm.
TubeWorld heavy_tube() {
  TubeWorld t;
  t.world.model.solver = default_solver();
  VesselParams p = default_vessel_params();
  p.centerline = {Vec3::Zero(), Vec3(0, 0, 0.03)};
  p.coarse_segments = kSegments;
  p.coarse_rings = kRings;
  p.fine_rings = 2 * kRings;
  p.object.total_mass = 0.1;
  p.object.gravity = true;
  p.object.coarse = false;
  p.object.linear_damping = 0.3;  // settles in a second; the rest is the same
  t.mesh = add_vessel(t.world, p).mesh;
  const MeshObject& m = t.world.meshes[t.mesh];
  for (std::uint32_t k = 0; k < kSegments; ++k) {
    t.world.state.particles.fix(m.first_particle + k);
    t.world.state.particles.fix(m.first_particle + (kRings - 1) * kSegments + k);
  }
  finish_setup(t.world);
  return t;
}

// The middle ring's mean fall (unit: m).
double middle_sag(const TubeWorld& t) {
  const MeshObject& m = t.world.meshes[t.mesh];
  const physics::Particles& P = t.world.state.particles;
  double sag = 0;
  for (std::uint32_t k = 0; k < kSegments; ++k) {
    const std::uint32_t i = m.first_particle + (kRings / 2) * kSegments + k;
    sag += P.rest_position[i].y() - P.position[i].y();
  }
  return sag / kSegments;
}

TEST(ImplicitRows, TheVesselsTubeRestsWhereItsXpbdRowsConverge) {
  TubeWorld xpbd = heavy_tube();
  physics::Executor exec(1);
  for (int n = 0; n < 400; ++n)
    ASSERT_TRUE(step_tissue(xpbd.world, exec).ok());
  const double settled = middle_sag(xpbd);

  TubeWorld implicit = heavy_tube();
  const MeshObject& m = implicit.world.meshes[implicit.mesh];
  physics::ImplicitMembrane membrane =
      implicit_membrane_of_rows(implicit.world, implicit.mesh, 100);
  EXPECT_EQ(membrane.free_count(), (kRings - 2) * kSegments);
  physics::Particles& P = implicit.world.state.particles;
  std::vector<Vec3> x(P.position.begin() + m.first_particle,
                      P.position.begin() + m.first_particle + m.particle_count);
  std::vector<Vec3> v(x.size(), Vec3::Zero());
  physics::ImplicitSolveParams exact;
  exact.tolerance = 1e-6;  // N, of the tube's 9.8 N weight (Phi's rounding: about 4e-8 N)
  // The weight as a force, not as gravity: over a step of 100 s gravity would put the inertial
  // target y = x + h^2 g 98 km below, and Phi's rounding there would end the solve early.
  std::vector<Vec3> weight(x.size(), Vec3::Zero());
  for (std::uint32_t k = 0; k < m.particle_count; ++k) {
    const Real w = P.inverse_mass[m.first_particle + k];
    if (w > 0) weight[k] = Vec3(0, -9.81, 0) / w;
  }
  physics::ImplicitLoads loads;
  loads.force = weight;
  const physics::ImplicitStepReport r = membrane.step(x, v, loads, exact);  // h = 100 s: static
  ASSERT_TRUE(r.ok);
  EXPECT_LT(r.residual, 1e-6) << r.iterations << " iterations";
  std::copy(x.begin(), x.end(), P.position.begin() + m.first_particle);
  const double solved = middle_sag(implicit);
  EXPECT_GT(solved, 2e-5);
  EXPECT_NEAR(solved, settled, 1e-4 * solved) << "XPBD " << settled << " m, implicit " << solved
                                              << " m in " << r.iterations << " iterations";
}

TEST(ImplicitRows, RefusesAMeshOutOfRange) {
  TubeWorld t = heavy_tube();
  EXPECT_THROW(implicit_membrane_of_rows(t.world, 7, 0.005), std::invalid_argument);
}

}  // namespace
}  // namespace imasim::tissue
