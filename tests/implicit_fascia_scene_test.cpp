// The thorax scene with its fascia solved by the implicit membrane step
// (scene/implicit_fascia_scene.hpp): the fascia's XPBD rows leave the constraint system, its
// contacts leave the XPBD set for the implicit step's planes, its particles keep their mass
// between steps, and the beating scene steps with no tissue inside the heart. The rest against
// converged XPBD is in convergence_test.cpp (label physics).
#include <gtest/gtest.h>

#include "physics/executor.hpp"
#include "scene/thorax_scene.hpp"
#include "tissue/mesh_object.hpp"

namespace imasim::scene {
namespace {

physics::StiffeningMembrane fascia_law() {
  const physics::MembraneMaterial m = tissue::default_fascia_membrane();
  return {m.youngs_modulus, Real(2.65e6), Real(0.05), m.thickness, Real(1100)};
}

TEST(ImplicitFasciaScene, TheFasciasRowsLeaveAndTheBeatingSceneStepsWithNothingInTheHeart) {
  ThoraxScene s = make_thorax_scene(default_thorax_scene_params());
  tissue::TissueWorld& w = s.patch.world;
  const tissue::MeshObject& fascia = w.meshes[s.patch.fascia];
  const std::size_t distance = w.state.constraints.distance.size();
  const std::size_t dihedral = w.state.constraints.dihedral.size();
  std::size_t edges = 0, interior = 0;
  for (const auto& [key, record] : fascia.edges) {
    edges += w.state.constraints.distance.resolves(record.distance);
    interior += w.state.constraints.dihedral.resolves(record.dihedral);
  }
  use_implicit_fascia(s, fascia_law());
  EXPECT_EQ(w.state.constraints.distance.size(), distance - edges);
  EXPECT_EQ(w.state.constraints.dihedral.size(), dihedral - interior);
  const std::uint32_t first = fascia.first_particle, end = first + fascia.particle_count;
  const std::vector<Real> mass_before = w.state.particles.inverse_mass;
  physics::Executor exec(1);
  std::size_t fascia_contacts = 0;
  for (int n = 0; n < 100; ++n) {  // 0.5 s
    ASSERT_TRUE(step_thorax_scene(s, exec).ok()) << "step " << n;
    ASSERT_TRUE(s.implicit_fascia->last.ok);
    fascia_contacts += s.implicit_fascia->contacts.size();
    for (const physics::ContactRow& c : w.state.contacts.rows)
      EXPECT_FALSE(c.particle >= first && c.particle < end) << "a fascia row left in XPBD's set";
  }
  EXPECT_EQ(w.state.particles.inverse_mass, mass_before);
  EXPECT_GT(fascia_contacts, 0u);  // the fascia met the surfaces through the implicit step
  const physics::Particles& P = w.state.particles;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.inverse_mass[i] == 0) continue;
    EXPECT_GE(tissue::heart_signed_distance(s.heart, P.position[i], 0.03), 0.0) << "particle " << i;
  }
  EXPECT_GT(tissue::max_displacement(w, fascia), 0.5e-3);  // it sagged: the implicit step moved it
}

}  // namespace
}  // namespace imasim::scene
