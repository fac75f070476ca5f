// The cloth verification scene: its contract (counts, centre, masses) and its physics (comes to
// rest, fixed vertices never move, XPBD sag converges as substeps grow).
#include <gtest/gtest.h>

#include "precision.hpp"

#include <cmath>
#include <limits>

#include "physics/executor.hpp"
#include "physics/step.hpp"
#include "scene/cloth_scene.hpp"

namespace imasim::scene {
namespace {

double kinetic_energy(const physics::State& s) {
  double e = 0;
  for (std::size_t i = 0; i < s.particles.size(); ++i) {
    if (s.particles.inverse_mass[i] > 0) {
      e += 0.5 * s.particles.velocity[i].squaredNorm() / s.particles.inverse_mass[i];
    }
  }
  return e;
}

TEST(ClothScene, MatchesItsContract) {
  for (const std::uint32_t n : {5u, 6u, 32u}) {
    ClothParams p;
    p.n = n;
    p.size = 2;
    p.mass = 3;
    const ClothScene s = make_cloth_scene(p);
    const auto& P = s.state.particles;
    ASSERT_EQ(P.size(), n * n);
    const std::size_t edges = 3 * (n - 1) * (n - 1) + 2 * (n - 1);
    EXPECT_EQ(s.state.constraints.distance.size(), edges);
    EXPECT_EQ(s.state.constraints.dihedral.size(), edges - 4 * (n - 1));
    EXPECT_EQ(P.position[n * n - 1], Vec3(2, 0, 2));
    std::size_t fixed = 0;
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (P.is_fixed(static_cast<std::uint32_t>(i))) {
        ++fixed;
      } else {
        // eq. 5 over all N^2 vertices
        EXPECT_NEAR(1 / P.inverse_mass[i], 3.0 / (n * n), test::ulps(4, 3.0 / (n * n)));
      }
    }
    EXPECT_EQ(fixed, 4 * (n - 1));
    EXPECT_EQ(s.centre_particles.size(), n % 2 == 0 ? 4u : 1u);
    Vec3 mean = Vec3::Zero();
    const double half_spacing = 0.5 * 2.0 / (n - 1);
    for (std::uint32_t c : s.centre_particles) {
      mean += P.position[c] / double(s.centre_particles.size());
      // The centre particles are the vertices nearest the middle of the square.
      EXPECT_NEAR(std::abs(P.position[c].x() - 1.0), n % 2 == 0 ? half_spacing : 0.0,
                  test::ulps(2, 2));
      EXPECT_NEAR(std::abs(P.position[c].z() - 1.0), n % 2 == 0 ? half_spacing : 0.0,
                  test::ulps(2, 2));
    }
    EXPECT_NEAR(mean.x(), 1.0, test::ulps(4, 2));
    EXPECT_NEAR(mean.z(), 1.0, test::ulps(4, 2));
  }
}

TEST(ClothScene, RejectsBadParameters) {
  ClothParams p;
  p.n = 2;
  EXPECT_THROW(make_cloth_scene(p), std::invalid_argument);
  p.n = 8;
  p.mass = -1;
  EXPECT_THROW(make_cloth_scene(p), std::invalid_argument);
  p.mass = 1;
  p.pbd_bending_stiffness = 1.5;
  EXPECT_THROW(make_cloth_scene(p), std::invalid_argument);
}

// With XPBD compliance the sheet can stretch, so its equilibrium is well posed. (With PBD
// stiffness 1 an inextensible sheet with a fixed perimeter has no equilibrium other than flat;
// it sags only through unconverged iterations and keeps a Gauss-Seidel jitter of about 1e-8 J:
// docs/physics.md.)
TEST(ClothScene, HangingClothComesToRestAndFixedVerticesNeverMove) {
  ClothParams p;
  p.n = 16;
  p.response = physics::Response::xpbd;
  p.distance_compliance = 1e-6;
  p.bending_compliance = 1;
  p.linear_damping = 0.05;
  ClothScene s = make_cloth_scene(p);
  physics::Executor exec(2);
  const auto rest = s.state.particles.position;
  double peak = 0;
  for (int n = 0; n < 3000; ++n) {
    ASSERT_TRUE(physics::step(s.model, s.state, exec).ok());
    peak = std::max(peak, kinetic_energy(s.state));
    for (std::size_t i = 0; i < rest.size(); ++i) {
      if (s.state.particles.is_fixed(static_cast<std::uint32_t>(i))) {
        ASSERT_EQ(s.state.particles.position[i], rest[i]) << "fixed vertex " << i << " moved";
      }
    }
  }
  EXPECT_GT(peak, 1e-4);  // it did move
  // At rest the velocities (p - x)/dt are the rounding of positions of about 1 m: the kinetic
  // energy floor is 0.5 M (eps * 1 m / dt)^2 (3e-22 J in double, 3e-10 J in float).
  const double v_noise = test::ulps(1, 1.0) / p.dt;
  EXPECT_LT(kinetic_energy(s.state), 0.5 * p.mass * v_noise * v_noise);
  EXPECT_GT(centre_sag(s), 0.0);
}

double xpbd_rest_sag(std::uint32_t substeps) {
  ClothParams p;
  p.n = 12;
  p.response = physics::Response::xpbd;
  p.distance_compliance = 2e-3;  // soft enough that the sag depends on it (m/N)
  p.bending_compliance = 10;     // (rad/(N m))
  p.iterations = 2;
  p.substeps = substeps;
  p.linear_damping = 0.2;
  ClothScene s = make_cloth_scene(p);
  physics::Executor exec(1);
  for (int n = 0; n < 1500; ++n)
    EXPECT_TRUE(physics::step(s.model, s.state, exec).ok());
  return centre_sag(s);
}

TEST(ClothScene, XpbdSagConvergesAsSubstepsGrow) {
  // 1, 2, 4, 8 and 16 substeps (h down to 0.3125 ms). In a float build the rounding of
  // v = (p - x)/h at 1 m scale (2e-4 m/s at 16 substeps) would dominate the last change.
  constexpr int kLevels = std::numeric_limits<Real>::digits > 24 ? 5 : 4;
  double sag[kLevels];
  for (int k = 0; k < kLevels; ++k)
    sag[k] = xpbd_rest_sag(1u << k);
  double previous_change = std::abs(sag[1] - sag[0]);
  EXPECT_GT(previous_change, 0.0);
  for (int k = 2; k < kLevels; ++k) {
    const double change = std::abs(sag[k] - sag[k - 1]);
    EXPECT_LT(change, previous_change) << "substeps " << (1 << k);
    previous_change = change;
  }
  EXPECT_LT(previous_change, 0.01 * sag[kLevels - 1]);
}

}  // namespace
}  // namespace imasim::scene
