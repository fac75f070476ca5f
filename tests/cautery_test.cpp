// Electrocautery: the thermal dose grows only while the pedal is pressed and the electrode
// touches tissue, by exactly the heat share of P dt; coagulated tissue stiffens.
#include "surgery/cautery.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "tissue/thoracic_patch.hpp"

namespace imasim::surgery {
namespace {

Real total_dose(const CauteryState& s) {
  return std::accumulate(s.dose.begin(), s.dose.end(), Real(0));
}

// The default patch with the fascia heatable, and an interior fascia vertex v with the
// electrode a-b passing through it across the sheet.
struct HeatedFascia {
  tissue::ThoracicPatch patch =
      tissue::make_thoracic_patch(tissue::default_thoracic_patch_params());
  CauteryParams params;
  CauteryState state =
      make_cautery_state(patch.world, params, {patch.world.meshes[patch.fascia].object},
                         patch.world.meshes[patch.ima].object);
  std::uint32_t v = patch.world.meshes[patch.fascia].first_particle + 5 * 12 + 6;
  Vec3 a = patch.world.state.particles.position[v] - Vec3(0, 0.004, 0);
  Vec3 b = patch.world.state.particles.position[v] + Vec3(0, 0.004, 0);
};

TEST(Cautery, DoseGrowsOnlyWhileThePedalIsPressedAndTheToolTouchesTissue) {
  HeatedFascia h;
  tissue::TissueWorld& w = h.patch.world;
  const CauteryParams& params = h.params;
  CauteryState& state = h.state;
  const std::uint32_t v = h.v;
  ASSERT_FALSE(w.state.particles.is_fixed(v));
  const Vec3 a = h.a, b = h.b;
  const Vec3 away = Vec3(0, -0.05, 0);
  const Real dt = 0.005;
  // Touching, pedal up: nothing.
  for (int n = 0; n < 10; ++n) {
    const CauteryStep s = apply_cautery(w, params, PedalMode::off, a, b, dt, state);
    EXPECT_FALSE(s.active);
    EXPECT_EQ(s.energy, 0);
  }
  EXPECT_EQ(total_dose(state), 0);
  // Touching, pedal down: eta P dt per step, all of it into the tissue.
  for (int n = 1; n <= 10; ++n) {
    const CauteryStep s = apply_cautery(w, params, PedalMode::coag, a, b, dt, state);
    EXPECT_GT(s.touching, 0u);
    EXPECT_EQ(s.energy, params.coag_heat_fraction * params.power * dt);
    EXPECT_NEAR(total_dose(state), n * params.coag_heat_fraction * params.power * dt, 1e-12);
  }
  EXPECT_GT(state.dose[v], 0);
  // The most at the electrode: v receives more than any other particle.
  for (std::size_t i = 0; i < state.dose.size(); ++i)
    EXPECT_LE(state.dose[i], state.dose[v]);
  const Real after_contact = total_dose(state);
  // Pedal down, not touching: nothing more.
  for (int n = 0; n < 10; ++n) {
    const CauteryStep s = apply_cautery(w, params, PedalMode::cut, a + away, b + away, dt, state);
    EXPECT_EQ(s.touching, 0u);
    EXPECT_EQ(s.energy, 0);
  }
  EXPECT_EQ(total_dose(state), after_contact);
  // Cut mode heats less than coagulation (eta 0.2 against 0.6).
  const CauteryStep cut = apply_cautery(w, params, PedalMode::cut, a, b, dt, state);
  EXPECT_EQ(cut.energy, params.cut_heat_fraction * params.power * dt);
}

TEST(Cautery, CoagulatedTissueStiffens) {
  HeatedFascia h;
  tissue::TissueWorld& w = h.patch.world;
  const CauteryParams& params = h.params;
  CauteryState& state = h.state;
  const tissue::MeshObject& fascia = w.meshes[h.patch.fascia];
  const std::uint32_t v = h.v;
  std::uint32_t coagulated = 0;
  for (int n = 0; n < 400 && !state.coagulated[v]; ++n)
    coagulated += apply_cautery(w, params, PedalMode::coag, h.a, h.b, 0.005, state).coagulated;
  ASSERT_TRUE(state.coagulated[v]);
  EXPECT_GE(temperature_rise(w, params, state, v), params.coagulation_rise);
  EXPECT_GT(coagulated, 0u);
  // dT = Q / (m c).
  EXPECT_NEAR(temperature_rise(w, params, state, v),
              state.dose[v] * w.state.particles.inverse_mass[v] / params.specific_heat, 1e-12);
  // Its edges' stretch compliance is a tenth of the fascia's own.
  const Real own = w.model.materials[fascia.stretch_material].compliance;
  int edges = 0;
  for (const auto& g : w.state.constraints.distance.groups()) {
    for (const physics::DistanceRow& r : g.rows) {
      if (r.i != v && r.j != v) continue;
      EXPECT_NEAR(w.model.materials[r.material].compliance,
                  own * params.coagulated_compliance_factor, 1e-20);
      ++edges;
    }
  }
  std::vector<std::uint32_t> neighbours;  // the vertex's edges, from the mesh
  for (const geometry::Triangle& t : fascia.triangles) {
    for (std::uint32_t u : t) {
      const bool has_v = t[0] + fascia.first_particle == v || t[1] + fascia.first_particle == v ||
                         t[2] + fascia.first_particle == v;
      if (has_v && u + fascia.first_particle != v) neighbours.push_back(u);
    }
  }
  std::sort(neighbours.begin(), neighbours.end());
  neighbours.erase(std::unique(neighbours.begin(), neighbours.end()), neighbours.end());
  EXPECT_EQ(edges, int(neighbours.size()));
  EXPECT_GE(edges, 4);
  // Colour: fully the coagulated colour at the coagulation rise, the base colour at none.
  const Vec3 base(0.9, 0.5, 0.5);
  EXPECT_EQ(coagulation_colour(base, 0, params), base);
  EXPECT_EQ(coagulation_colour(base, params.coagulation_rise, params),
            coagulation_colour(Vec3::Zero(), 100, params));
}

TEST(Cautery, PowerOutsideThirtyToFiftyWattsIsRefused) {
  CauteryParams p;
  p.power = 60;
  EXPECT_THROW(validate(p), std::invalid_argument);
  p.power = 29;
  EXPECT_THROW(validate(p), std::invalid_argument);
  p.power = 30;
  EXPECT_NO_THROW(validate(p));
}

}  // namespace
}  // namespace imasim::surgery
