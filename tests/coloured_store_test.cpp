// Constraint colouring: valid after building, after random additions and removals, with an
// overflow colour once the regular colours run out; handles go stale on removal.
#include <gtest/gtest.h>

#include <random>

#include "physics/constraint_system.hpp"
#include "physics/validation.hpp"
#include "scene/cloth_scene.hpp"

namespace imasim::physics {
namespace {

struct World {
  Model model;
  State state;
  MaterialId material = 0;

  explicit World(std::uint32_t particles) {
    model.objects.push_back({});
    material = model.add_material(ConstraintMaterial::xpbd(0));
    for (std::uint32_t i = 0; i < particles; ++i) {
      state.particles.add(Vec3(Real(i), 0, 0), 1, 0);
    }
    prepare_state(model, state);
  }
};

TEST(ColouredStore, ClothSceneColouringIsValid) {
  scene::ClothParams p;
  p.n = 24;
  scene::ClothScene s = scene::make_cloth_scene(p);
  EXPECT_EQ(validate_state(s.model, s.state), "");
  EXPECT_EQ(s.state.constraints.overflow_size(), 0u);
  // An edge colouring of a grid needs at least max-degree (6) colours.
  EXPECT_GE(s.state.constraints.distance.non_empty_groups(), 6u);
}

TEST(ColouredStore, OverflowTakesWhatDoesNotFit) {
  // 40 constraints all sharing particle 0, all of band 0 (fine objects): the distance store
  // gives band 0 colours 0-23, so 24 coloured and 16 in band 0's overflow group.
  World w(41);
  for (std::uint32_t i = 1; i <= 40; ++i)
    add_distance(w.state.constraints, w.state.particles, 0, i, w.material);
  const auto& store = w.state.constraints.distance;
  EXPECT_EQ(store.size(), 40u);
  EXPECT_EQ(store.band_end(0), 24u);
  EXPECT_EQ(store.overflow_size(), 16u);
  EXPECT_EQ(store.groups()[ColouredStore<DistanceRow>::overflow_group(0)].rows.size(), 16u);
  EXPECT_EQ(store.non_empty_groups(), 25u);
  EXPECT_EQ(validate_state(w.model, w.state), "");
}

TEST(ColouredStore, ACoarseObjectsRowsColourInBandOne) {
  // Band 1 (a coarse object's rows, projected at the coarse rate) has colours 24-31 and its own
  // overflow group, so the two bands never share a colour group.
  World w(41);
  w.model.objects.push_back(ObjectParams{});
  w.model.objects.back().coarse = true;
  w.state.constraints.set_object_band(1, true);
  for (std::uint32_t i = 0; i <= 40; ++i)
    w.state.particles.object[i] = 1;
  for (std::uint32_t i = 1; i <= 10; ++i)
    add_distance(w.state.constraints, w.state.particles, 0, i, w.material);
  const auto& store = w.state.constraints.distance;
  const auto groups = store.groups();
  for (std::uint32_t g = 0; g < 24; ++g)
    EXPECT_TRUE(groups[g].rows.empty()) << g;
  for (std::uint32_t g = 24; g < 32; ++g)
    EXPECT_EQ(groups[g].rows.size(), 1u) << g;
  EXPECT_EQ(groups[ColouredStore<DistanceRow>::overflow_group(1)].rows.size(), 2u);
  EXPECT_EQ(validate_state(w.model, w.state), "");
}

TEST(ColouredStore, RemovalFreesTheColourAndStaleHandlesFail) {
  World w(3);
  ConstraintSystem& cs = w.state.constraints;
  const DistanceHandle a = add_distance(cs, w.state.particles, 0, 1, w.material);
  const DistanceHandle b = add_distance(cs, w.state.particles, 1, 2, w.material);
  EXPECT_NE(cs.distance.particle_colour_mask(1), 0u);
  ASSERT_TRUE(cs.distance.remove(a));
  EXPECT_FALSE(cs.distance.remove(a));
  EXPECT_EQ(cs.distance.find(a), nullptr);
  ASSERT_NE(cs.distance.find(b), nullptr);
  EXPECT_EQ(cs.distance.find(b)->i, 1u);
  // The slot is reused with a new generation: the old handle still does not resolve.
  const DistanceHandle c = add_distance(cs, w.state.particles, 0, 2, w.material);
  EXPECT_EQ(c.index, a.index);
  EXPECT_NE(c.generation, a.generation);
  EXPECT_EQ(cs.distance.find(a), nullptr);
  EXPECT_EQ(validate_state(w.model, w.state), "");
}

TEST(ColouredStore, StaysValidUnderRandomAdditionsAndRemovals) {
  const std::uint32_t n = 60;
  World w(n);
  ConstraintSystem& cs = w.state.constraints;
  std::mt19937 rng(7);
  std::uniform_int_distribution<std::uint32_t> pick(0, n - 1);
  std::vector<DistanceHandle> distance;
  std::vector<DihedralHandle> dihedral;
  for (int op = 0; op < 5000; ++op) {
    const int kind = static_cast<int>(rng() % 4);
    if (kind == 0 || distance.empty()) {
      const std::uint32_t i = pick(rng), j = (i + 1 + pick(rng) % (n - 1)) % n;
      distance.push_back(add_distance(cs, w.state.particles, i, j, w.material));
    } else if (kind == 1) {
      std::uint32_t p[4] = {pick(rng), 0, 0, 0};
      for (int k = 1; k < 4; ++k)
        p[k] = (p[k - 1] + 1 + pick(rng) % 5) % n;
      dihedral.push_back(add_dihedral(cs, w.state.particles, p[0], p[1], p[2], p[3], w.material));
    } else if (kind == 2) {
      const std::size_t k = rng() % distance.size();
      ASSERT_TRUE(cs.distance.remove(distance[k]));
      distance[k] = distance.back();
      distance.pop_back();
    } else if (!dihedral.empty()) {
      const std::size_t k = rng() % dihedral.size();
      ASSERT_TRUE(cs.dihedral.remove(dihedral[k]));
      dihedral[k] = dihedral.back();
      dihedral.pop_back();
    }
    if (op % 250 == 0) {
      ASSERT_EQ(validate_state(w.model, w.state), "") << "after op " << op;
    }
  }
  EXPECT_EQ(cs.distance.size(), distance.size());
  EXPECT_EQ(cs.dihedral.size(), dihedral.size());
  for (const DistanceHandle& h : distance)
    EXPECT_NE(cs.distance.find(h), nullptr);
  EXPECT_EQ(validate_state(w.model, w.state), "");
}

TEST(ColouredStore, ValidationCatchesABrokenColouring) {
  World w(3);
  ConstraintSystem& cs = w.state.constraints;
  add_distance(cs, w.state.particles, 0, 1, w.material);
  add_distance(cs, w.state.particles, 1, 2, w.material);
  // Force both rows into colour 0: particle 1 then appears twice in one colour.
  auto groups = cs.distance.groups();
  ASSERT_EQ(groups[0].rows.size(), 1u);
  ASSERT_EQ(groups[1].rows.size(), 1u);
  groups[0].rows.push_back(groups[1].rows[0]);
  groups[0].lambda.push_back(0);
  EXPECT_NE(validate_state(w.model, w.state).find("twice"), std::string::npos);
}

TEST(ConstraintSystem, RejectsConstraintsOnMissingParticles) {
  World w(2);
  EXPECT_THROW(add_distance(w.state.constraints, w.state.particles, 0, 5, w.material),
               std::out_of_range);
  EXPECT_THROW(add_distance(w.state.constraints, w.state.particles, 1, 1, w.material),
               std::invalid_argument);
  EXPECT_THROW(add_attachment(w.state.constraints, w.state.particles, 9, Vec3::Zero(), w.material),
               std::out_of_range);
}

}  // namespace
}  // namespace imasim::physics
