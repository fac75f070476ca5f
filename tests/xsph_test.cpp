// XSPH velocity smoothing of the fat (SPEC S2): a common motion is left alone, a particle moving
// against its neighbours is pulled towards them, each pair normalised symmetrically, so each
// set's momentum is kept while relative motion is damped.
#include <gtest/gtest.h>

#include <algorithm>
#include <random>
#include <vector>

#include "physics/executor.hpp"
#include "precision.hpp"
#include "tissue/strands.hpp"
#include "tissue/thoracic_patch.hpp"
#include "tissue/xsph.hpp"

namespace imasim::tissue {
namespace {

TEST(Xsph, LeavesACommonVelocityAlone) {
  ThoracicPatch patch = make_thoracic_patch(default_thoracic_patch_params());
  TissueWorld& w = patch.world;
  for (Vec3& v : w.state.particles.velocity)
    v = Vec3(0.01, -0.02, 0.005);
  smooth_strand_velocities(w);
  for (const Vec3& v : w.state.particles.velocity) {
    EXPECT_LT((v - Vec3(0.01, -0.02, 0.005)).norm(), test::ulps(8, 0.03));
  }
}

// W_ij of the smoothing, from the current positions.
Real kernel(const TissueWorld& w, const StrandSet& set, std::uint32_t i, std::uint32_t j) {
  const Real r = (w.state.particles.position[j] - w.state.particles.position[i]).norm();
  return r < set.xsph_radius ? (1 - r / set.xsph_radius) * (1 - r / set.xsph_radius) : Real(0);
}

// The neighbours of the set's particle k, from the pair list (each pair is listed once, from its
// lower index), ascending.
std::vector<std::uint32_t> neighbours_of(const StrandSet& set, std::uint32_t k) {
  std::vector<std::uint32_t> out;
  for (std::size_t p = 0; p < set.pair_lower.size(); ++p) {
    if (set.pair_upper[p] == k) out.push_back(set.pair_lower[p]);
  }
  for (std::uint32_t p = set.pair_start[k]; p < set.pair_start[k + 1]; ++p)
    out.push_back(set.pair_upper[p]);
  return out;
}

// S_k = sum_j W_kj over the neighbours of the set's particle k.
Real weight_sum(const TissueWorld& w, const StrandSet& set, std::uint32_t k) {
  Real sum = 0;
  for (std::uint32_t j : neighbours_of(set, k))
    sum += kernel(w, set, set.first_particle + k, set.first_particle + j);
  return sum;
}

// The pair list against a search of every pair: each pair of interior particles (not a strand's
// ends, which sit on the membranes) closer than the radius at rest, once, from its lower index.
TEST(Xsph, PairsAreEveryInteriorPairWithinTheRadiusAtRestOnce) {
  ThoracicPatch patch = make_thoracic_patch(default_thoracic_patch_params());
  const TissueWorld& w = patch.world;
  ASSERT_FALSE(w.strands.empty());
  for (const StrandSet& set : w.strands) {
    SCOPED_TRACE(set.name);
    const std::uint32_t count = set.particle_count(), per = set.segments + 1;
    ASSERT_EQ(set.pair_start.size(), std::size_t(count) + 1);
    ASSERT_EQ(set.pair_lower.size(), set.pair_upper.size());
    ASSERT_EQ(set.pair_start.back(), set.pair_lower.size());
    auto interior = [&](std::uint32_t k) { return k % per != 0 && k % per != set.segments; };
    std::size_t expected = 0;
    for (std::uint32_t k = 0; k < count; ++k) {
      std::vector<std::uint32_t> within;
      for (std::uint32_t j = k + 1; j < count && interior(k); ++j) {
        const Vec3 d = w.state.particles.rest_position[set.first_particle + j] -
                       w.state.particles.rest_position[set.first_particle + k];
        if (interior(j) && d.squaredNorm() < set.xsph_radius * set.xsph_radius) within.push_back(j);
      }
      const std::vector<std::uint32_t> listed(set.pair_upper.begin() + set.pair_start[k],
                                              set.pair_upper.begin() + set.pair_start[k + 1]);
      ASSERT_EQ(listed, within) << "particle " << k;
      for (std::uint32_t p = set.pair_start[k]; p < set.pair_start[k + 1]; ++p)
        ASSERT_EQ(set.pair_lower[p], k);
      expected += within.size();
    }
    EXPECT_EQ(set.pair_lower.size(), expected);
    EXPECT_GT(expected, std::size_t(count));  // the radius reaches across strands
  }
}

// The incoming lists: every pair once, under its upper particle, in ascending order (the order in
// which a pass over the pairs from their lower particles reaches them).
TEST(Xsph, IncomingListsHoldEachPairUnderItsUpperParticleInOrder) {
  ThoracicPatch patch = make_thoracic_patch(default_thoracic_patch_params());
  for (const StrandSet& set : patch.world.strands) {
    SCOPED_TRACE(set.name);
    ASSERT_EQ(set.incoming_start.size(), std::size_t(set.particle_count()) + 1);
    ASSERT_EQ(set.incoming_pair.size(), set.pair_upper.size());
    std::vector<int> seen(set.pair_upper.size(), 0);
    for (std::uint32_t k = 0; k < set.particle_count(); ++k) {
      for (std::uint32_t q = set.incoming_start[k]; q < set.incoming_start[k + 1]; ++q) {
        const std::uint32_t p = set.incoming_pair[q];
        ASSERT_EQ(set.pair_upper[p], k);
        if (q > set.incoming_start[k]) {
          ASSERT_LT(set.incoming_pair[q - 1], p);
        }
        ++seen[p];
      }
    }
    for (const int n : seen)
      ASSERT_EQ(n, 1);
  }
}

// Several chunks of pairs and of particles (the fascia's fat: thousands of each), strands cut
// among them: two threads give the velocities of one, bit for bit.
TEST(Xsph, TwoThreadsSmoothAsOne) {
  ThoracicPatch patch = make_thoracic_patch(default_thoracic_patch_params());
  TissueWorld& w = patch.world;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<Real> u(-0.02, 0.02);  // (unit: m/s)
  for (Vec3& v : w.state.particles.velocity)
    v = Vec3(u(rng), u(rng), u(rng));
  StrandSet& set = w.strands[patch.fascia_fat];
  ASSERT_GT(set.pair_lower.size(), 8000u);
  for (std::uint32_t k = 0; k < set.particle_count(); k += 97)  // removed by cuts
    set.diameter[k] = 0;
  TissueWorld other = w;
  const std::vector<Vec3> before = w.state.particles.velocity;
  const physics::Executor serial(1), pair(2);
  smooth_strand_velocities(w, serial);
  smooth_strand_velocities(other, pair);
  EXPECT_EQ(w.state.particles.velocity, other.state.particles.velocity);
  EXPECT_NE(w.state.particles.velocity, before);  // and the smoothing did act
}

TEST(Xsph, PullsAnOutlierTowardsItsNeighbours) {
  ThoracicPatch patch = make_thoracic_patch(default_thoracic_patch_params());
  TissueWorld& w = patch.world;
  const StrandSet& set = w.strands[patch.fascia_fat];
  for (Vec3& v : w.state.particles.velocity)
    v.setZero();
  // The interior particle with the most neighbours moves at 1 cm/s along x.
  std::uint32_t k_best = 0, most = 0;
  std::vector<std::uint32_t> count(set.particle_count(), 0);
  for (std::size_t p = 0; p < set.pair_lower.size(); ++p)
    ++count[set.pair_lower[p]], ++count[set.pair_upper[p]];
  for (std::uint32_t k = 0; k < set.particle_count(); ++k) {
    const std::uint32_t n = count[k];
    if (n > most) most = n, k_best = k;
  }
  ASSERT_GT(most, 2u);
  const std::uint32_t i = set.first_particle + k_best;
  w.state.particles.velocity[i] = Vec3(0.01, 0, 0);
  const Real c = set.xsph_coefficient, S_i = weight_sum(w, set, k_best);
  smooth_strand_velocities(w);
  // Its neighbours are at rest: v_i' = v_i (1 - c sum_j W_ij / max(S_i, S_j)), and each
  // neighbour gains what it loses, v_j' = c W_ij / max(S_i, S_j) v_i <= c v_i.
  Real kept = 1, given = 0;
  int moved = 0;
  for (std::uint32_t k : neighbours_of(set, k_best)) {
    const std::uint32_t j = set.first_particle + k;
    const Real share = c * kernel(w, set, i, j) / std::max(S_i, weight_sum(w, set, k));
    kept -= share;
    const double vx = w.state.particles.velocity[j].x();
    EXPECT_NEAR(vx, share * 0.01, 1e-17);
    EXPECT_LE(vx, c * 0.01);
    given += vx;
    moved += vx > 0 ? 1 : 0;
  }
  EXPECT_GT(moved, 0);
  EXPECT_NEAR(w.state.particles.velocity[i].x(), kept * 0.01, 1e-17);
  EXPECT_GE(kept, 1 - c);
  EXPECT_NEAR(w.state.particles.velocity[i].x() + given, 0.01, 1e-17);  // momentum kept
}

TEST(Xsph, KeepsEachSetsMomentumAndReducesRelativeMotion) {
  ThoracicPatch patch = make_thoracic_patch(default_thoracic_patch_params());
  TissueWorld& w = patch.world;
  physics::Particles& P = w.state.particles;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<Real> u(-0.02, 0.02);  // (unit: m/s)
  for (Vec3& v : P.velocity)
    v = Vec3(u(rng), u(rng), u(rng));
  struct Totals {
    Vec3 momentum = Vec3::Zero();  // sum m v (unit: kg m/s)
    Real magnitude = 0;            // sum m |v|, the scale of the rounding
    Real relative = 0;             // sum m |v - v_mean|^2, twice the kinetic energy about the mean
  };
  auto totals = [&](const StrandSet& set) {
    Totals t;
    Real mass = 0;
    for (std::uint32_t k = 0; k < set.particle_count(); ++k) {
      const std::uint32_t i = set.first_particle + k;
      if (P.is_fixed(i)) continue;
      const Real m = 1 / P.inverse_mass[i];
      t.momentum += m * P.velocity[i];
      t.magnitude += m * P.velocity[i].norm();
      mass += m;
    }
    const Vec3 mean = t.momentum / mass;
    for (std::uint32_t k = 0; k < set.particle_count(); ++k) {
      const std::uint32_t i = set.first_particle + k;
      if (!P.is_fixed(i)) t.relative += (P.velocity[i] - mean).squaredNorm() / P.inverse_mass[i];
    }
    return t;
  };
  std::vector<Totals> before;
  for (const StrandSet& set : w.strands)
    before.push_back(totals(set));
  const std::vector<Vec3> velocities = P.velocity;
  smooth_strand_velocities(w);
  ASSERT_FALSE(w.strands.empty());
  for (std::size_t s = 0; s < w.strands.size(); ++s) {
    SCOPED_TRACE(s);
    const StrandSet& set = w.strands[s];
    ASSERT_GT(set.xsph_coefficient, 0);
    // Equal masses within the set: the pairs' exchanges cancel, to rounding.
    const Real m0 = P.inverse_mass[set.particle(0, 1)];
    for (std::uint32_t i = 0; i < set.strand_count; ++i)
      for (std::uint32_t k = 1; k < set.segments; ++k)
        ASSERT_EQ(P.inverse_mass[set.particle(i, k)], m0);
    const Totals after = totals(set);
    EXPECT_LT((after.momentum - before[s].momentum).norm(),
              test::ulps(16, double(before[s].magnitude)));
    EXPECT_LT(after.relative, 0.9 * before[s].relative);
  }
  // Particles of no strand set keep their velocities, bit for bit.
  std::vector<bool> in_set(P.size(), false);
  for (const StrandSet& set : w.strands)
    for (std::uint32_t k = 0; k < set.particle_count(); ++k)
      in_set[set.first_particle + k] = true;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (!in_set[i]) {
      EXPECT_EQ(P.velocity[i], velocities[i]) << i;
    }
  }
}

TEST(TissueWorld, EachObjectKeepsItsOwnParameters) {
  const ThoracicPatch patch = make_thoracic_patch(default_thoracic_patch_params());
  const TissueWorld& w = patch.world;
  const auto& objects = w.model.objects;
  EXPECT_EQ(objects[w.meshes[patch.ima].object].gravity, Vec3::Zero());  // 2.3.2
  EXPECT_NE(objects[w.meshes[patch.fascia].object].gravity, Vec3::Zero());
  EXPECT_DOUBLE_EQ(objects[w.meshes[patch.fascia].object].linear_damping, 0.03);
  EXPECT_DOUBLE_EQ(objects[w.meshes[patch.fascia].object].angular_damping, 0.01);
  // Uniform mass per object (eq. 5): 6 g over the fascia's 480 vertices.
  const MeshObject& f = w.meshes[patch.fascia];
  const std::uint32_t inner = f.first_particle + 12 + 1;  // not on the fixed perimeter
  EXPECT_NEAR(1 / w.state.particles.inverse_mass[inner], 0.006 / 480, 1e-15);
  for (std::uint32_t k = 0; k < w.meshes[patch.wall].particle_count; ++k) {
    EXPECT_TRUE(w.state.particles.is_fixed(w.meshes[patch.wall].first_particle + k));
  }
}

TEST(TissueWorld, RejectsBadTissueParameters) {
  ThoracicPatchParams p = default_thoracic_patch_params();
  p.fascia_fat.xsph_coefficient = 2;
  EXPECT_THROW(make_thoracic_patch(p), std::invalid_argument);
  p = default_thoracic_patch_params();
  p.vessel.object.total_mass = 0;
  EXPECT_THROW(make_thoracic_patch(p), std::invalid_argument);
  p = default_thoracic_patch_params();
  p.ima_fat.generation.segments = 0;
  EXPECT_THROW(make_thoracic_patch(p), std::invalid_argument);
  TissueWorld w;
  geometry::TriangleMesh non_manifold;
  non_manifold.vertices = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(0, -1, 0),
                           Vec3(0, 0, 1)};
  non_manifold.triangles = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  MeshObjectParams params;
  params.name = "bad";
  EXPECT_THROW(add_mesh_object(w, non_manifold, params), std::invalid_argument);
  EXPECT_EQ(w.state.particles.size(), 0u);  // refused before anything was added
  EXPECT_TRUE(w.model.objects.empty());
}

}  // namespace
}  // namespace imasim::tissue
