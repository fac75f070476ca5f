// Electrocautery: the heat grows only while the pedal is pressed and the electrode touches
// tissue; a particle's rise is the line source's closed form at its distance, whatever its mass;
// the temperature rise is each particle's state (kept through cuts, inherited by the vertices a
// cut makes); coagulated tissue stiffens.
#include "surgery/cautery.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "geometry/edge_adjacency.hpp"
#include "surgery/fascia_cut.hpp"
#include "tissue/thoracic_patch.hpp"
#include "tissue/topology_change.hpp"

namespace imasim::surgery {
namespace {

// Heat held by the tissue, sum_i m_i c dT_i (unit: J).
Real stored_heat(const tissue::TissueWorld& w, const CauteryParams& p, const CauteryState& s) {
  Real heat = 0;
  for (std::size_t i = 0; i < s.rise.size(); ++i)
    if (s.rise[i] > 0) heat += s.rise[i] / w.state.particles.inverse_mass[i] * p.specific_heat;
  return heat;
}

// The closed form of one step's rise at distance r from an electrode a-b: the line source of
// length L with a Gaussian cross-section (sigma = spread / 2) holding E = eta P dt,
// E exp(-(r/sigma)^2) / (pi sigma^2 (L + sqrt(pi) sigma) rho c) (unit: K).
Real line_source_rise(const CauteryParams& p, Real eta, Real dt, Real length, Real r) {
  const Real sigma = p.spread_radius / 2, pi = Real(3.14159265358979323846);
  const Real volume = pi * sigma * sigma * (length + std::sqrt(pi) * sigma);
  return eta * p.power * dt * std::exp(-(r / sigma) * (r / sigma)) /
         (volume * p.density * p.specific_heat);
}

// Distance from x to the segment a-b.
Real distance_to(const Vec3& x, const Vec3& a, const Vec3& b) {
  const Real t = std::clamp((x - a).dot(b - a) / (b - a).squaredNorm(), Real(0), Real(1));
  return (x - (a + t * (b - a))).norm();
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
  h.params.spread_radius = Real(0.008);  // v's neighbours (3.6 mm away) too
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
  EXPECT_EQ(state.dose, 0);
  EXPECT_EQ(stored_heat(w, params, state), 0);
  // Touching, pedal down: eta P dt per step delivered; each reached particle rises by the line
  // source's closed form at its distance, and the heat the sampled particles hold is at most
  // what was delivered (the rest warms the tissue between them).
  for (int n = 1; n <= 10; ++n) {
    const CauteryStep s = apply_cautery(w, params, PedalMode::coag, a, b, dt, state);
    EXPECT_GT(s.touching, 0u);
    EXPECT_EQ(s.energy, params.coag_heat_fraction * params.power * dt);
    EXPECT_NEAR(state.dose, n * params.coag_heat_fraction * params.power * dt, 1e-15);
    EXPECT_GT(stored_heat(w, params, state), 0);
    EXPECT_LT(stored_heat(w, params, state), state.dose);
  }
  const physics::Particles& P = w.state.particles;
  int reached = 0;
  for (std::uint32_t i = 0; i < P.size(); ++i) {
    const Real r = distance_to(P.position[i], a, b);
    const bool heated = !P.is_fixed(i) && P.object[i] == P.object[v] && r <= params.spread_radius;
    const Real expected =
        heated ? 10 * line_source_rise(params, params.coag_heat_fraction, dt, (b - a).norm(), r)
               : 0;
    EXPECT_NEAR(state.rise[i], expected, 1e-12 + 1e-12 * expected) << i;
    reached += heated ? 1 : 0;
  }
  EXPECT_GT(reached, 4);  // more than the vertex under the electrode
  EXPECT_GT(temperature_rise(state, v), 0);
  // The hottest at the electrode.
  for (std::size_t i = 0; i < state.rise.size(); ++i)
    EXPECT_LE(state.rise[i], state.rise[v]);
  const Real after_contact = state.dose;
  // Pedal down, not touching: nothing more.
  for (int n = 0; n < 10; ++n) {
    const CauteryStep s = apply_cautery(w, params, PedalMode::cut, a + away, b + away, dt, state);
    EXPECT_EQ(s.touching, 0u);
    EXPECT_EQ(s.energy, 0);
  }
  EXPECT_EQ(state.dose, after_contact);
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
  EXPECT_GE(temperature_rise(state, v), params.coagulation_rise);
  EXPECT_GT(coagulated, 0u);
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

// Splits the fascia's edge (a, b) (mesh-local) at t as a cut does: one new vertex, the edge's
// faces each divided in two.
tissue::TopologyChange split_edge(tissue::TissueWorld& w, std::uint32_t mesh, std::uint32_t a,
                                  std::uint32_t b, Real t) {
  const tissue::MeshObject& m = w.meshes[mesh];
  const geometry::EdgeAdjacency adj = geometry::build_edge_adjacency(tissue::rest_mesh(w, m));
  const geometry::MeshEdge* edge = nullptr;
  for (const auto& e : adj.edges)
    if ((e.a == a && e.b == b) || (e.a == b && e.b == a)) edge = &e;
  if (!edge) {
    ADD_FAILURE() << "no edge (" << a << ", " << b << ")";
    return {};
  }
  const std::uint32_t n = m.particle_count;
  tissue::MeshEdit edit;
  edit.vertices.push_back({a, b, t});
  for (int k = 0; k < 2; ++k) {
    if (edge->faces[k] == geometry::kNoFace) continue;
    const std::uint32_t f = edge->faces[k], o = edge->opposite[k];
    const std::uint32_t from = k == 0 ? edge->a : edge->b, to = k == 0 ? edge->b : edge->a;
    edit.replaced.emplace_back(f, geometry::Triangle{from, n, o});
    edit.added.push_back({geometry::Triangle{n, to, o}, f});
  }
  return tissue::apply_mesh_edit(w, mesh, edit);
}

TEST(Cautery, ARiseIsKeptExactlyThroughACutThatChangesTheVertexCount) {
  HeatedFascia h;
  tissue::TissueWorld& w = h.patch.world;
  // Only the vertex under the electrode is reached (its neighbours are 3.6 mm away): its rise is
  // the line source's at r = 0.
  h.params.spread_radius = h.params.contact_radius;
  const tissue::MeshObject& fascia = w.meshes[h.patch.fascia];
  const physics::Particles& P = w.state.particles;
  const Real dt = 0.005, inverse_mass = P.inverse_mass[h.v];
  const CauteryStep step = apply_cautery(w, h.params, PedalMode::coag, h.a, h.b, dt, h.state);
  ASSERT_EQ(step.energy, h.params.coag_heat_fraction * h.params.power * dt);
  const Real rise = line_source_rise(h.params, h.params.coag_heat_fraction, dt, (h.b - h.a).norm(),
                                     distance_to(P.position[h.v], h.a, h.b));
  EXPECT_NEAR(temperature_rise(h.state, h.v), rise, 1e-12 * rise);
  std::vector<Real> before;
  for (std::uint32_t k = 0; k < fascia.particle_count; ++k)
    before.push_back(temperature_rise(h.state, fascia.first_particle + k));
  // A cut elsewhere adds a vertex: eq. 5 makes every dynamic vertex lighter (M / 481) ...
  const std::uint32_t row = 30 * 12;
  const std::uint32_t n = fascia.particle_count;
  ASSERT_EQ(split_edge(w, h.patch.fascia, row + 4, row + 5, Real(0.5)).status,
            tissue::EditStatus::applied);
  ASSERT_EQ(fascia.particle_count, n + 1);
  EXPECT_NE(P.inverse_mass[h.v], inverse_mass);
  // ... and no temperature changes: the rise is the particle's state, not dose / current mass.
  for (std::uint32_t k = 0; k < n; ++k)
    EXPECT_EQ(temperature_rise(h.state, fascia.first_particle + k), before[k]) << k;
  // Heat deposited after the cut raises it by the same amount: the rise depends on the
  // distance from the electrode, not on how finely the tissue is sampled.
  apply_cautery(w, h.params, PedalMode::coag, h.a, h.b, dt, h.state);
  EXPECT_NEAR(temperature_rise(h.state, h.v), 2 * rise, 1e-12 * rise);
}

TEST(Cautery, ANewVertexTakesItsParentsRiseInterpolatedLikeItsPosition) {
  HeatedFascia h;
  tissue::TissueWorld& w = h.patch.world;
  const std::uint32_t mesh = h.patch.fascia;
  const tissue::MeshObject& fascia = w.meshes[mesh];
  const std::uint32_t first = fascia.first_particle, v = h.v - first;
  CauteryState& s = h.state;
  // Known rises on v and three of its neighbours: 30 K (coagulated), 10 K, 10 K and 25 K
  // (coagulated); each split below divides another of v's edges.
  const std::uint32_t a = h.v, b = h.v + 1, d = h.v + 12, c = h.v - 1;
  s.rise[a] = 30, s.rise[b] = 10, s.rise[d] = 10, s.rise[c] = 25;
  s.coagulated[a] = s.coagulated[c] = 1;
  s.coagulated_count = 2;
  struct Case {
    std::uint32_t other;  // the second parent (mesh-local), the first is v
    Real t;               // weight of the second
    Real rise;            // (1 - t) dT_v + t dT_other
    bool coagulated;
  };
  // 0.7 * 30 + 0.3 * 10 = 24 K: past the 23 K coagulation rise though one parent is not;
  // 0.2 * 30 + 0.8 * 10 = 14 K: not; between two coagulated parents: coagulated.
  for (const Case& k :
       {Case{v + 1, Real(0.3), Real(24), true}, Case{v + 12, Real(0.8), Real(14), false},
        Case{v - 1, Real(0.5), Real(27.5), true}}) {
    SCOPED_TRACE(k.t);
    const tissue::TopologyChange change = split_edge(w, mesh, v, k.other, k.t);
    ASSERT_EQ(change.status, tissue::EditStatus::applied);
    const tissue::NewVertex made[1] = {{v, k.other, k.t}};
    inherit_cautery_state(w, h.params, mesh, change.first_new_vertex, made, s);
    const std::uint32_t i = first + change.first_new_vertex;
    EXPECT_NEAR(temperature_rise(s, i), k.rise, 1e-14);
    EXPECT_EQ(s.coagulated[i], k.coagulated ? 1 : 0);
    EXPECT_EQ(s.injured[i], 0);  // the fascia is not the IMA
  }
  EXPECT_EQ(s.coagulated_count, 4u);
  // The parents' rises are as they were.
  EXPECT_EQ(s.rise[a], 30);
  EXPECT_EQ(s.rise[b], 10);
  EXPECT_EQ(s.rise[d], 10);
  EXPECT_EQ(s.rise[c], 25);
}

TEST(Cautery, VerticesACutMakesThroughHeatedTissueKeepItsTemperature) {
  HeatedFascia h;
  tissue::TissueWorld& w = h.patch.world;
  h.params.spread_radius = Real(0.008);  // v's neighbours too, each by its share
  CauteryState& s = h.state;
  for (int n = 0; n < 2000 && !s.coagulated[h.v]; ++n)  // a wide source heats slowly
    apply_cautery(w, h.params, PedalMode::coag, h.a, h.b, 0.005, s);
  ASSERT_TRUE(s.coagulated[h.v]);
  const std::vector<Real> before = s.rise;
  // A blade across the sheet 0.5 mm beside v, drawn 12 mm along z through the heated area: the
  // edges it crosses are split, then the vertices on the cut copied to part the sides.
  const Vec3 x = w.state.particles.position[h.v];
  FasciaCutter cutter = make_fascia_cutter(h.patch.fascia);
  const FasciaCutResult cut = cut_fascia(
      w, {}, {x + Vec3(0.0005, -0.004, -0.006), Vec3(0, 0.008, 0), Vec3(0, 0, 0.012)}, cutter);
  ASSERT_EQ(cut.status, tissue::EditStatus::applied);
  ASSERT_GT(cut.edges_split, 0u);
  ASSERT_GT(cut.vertices_copied, 0u);
  ASSERT_EQ(cut.new_vertices.size(), cut.edges_split + cut.vertices_copied);
  const tissue::MeshObject& fascia = w.meshes[h.patch.fascia];
  ASSERT_EQ(cut.first_new_vertex + cut.new_vertices.size(), fascia.particle_count);
  inherit_cautery_state(w, h.params, h.patch.fascia, cut.first_new_vertex, cut.new_vertices, s);
  // Existing particles keep their rise though their mass changed; each new one takes its
  // parents', with the weight of its position (a copy: exactly its parent's).
  for (std::size_t i = 0; i < before.size(); ++i) {
    if (i >= fascia.first_particle + cut.first_new_vertex &&
        i < fascia.first_particle + fascia.particle_count) {
      continue;
    }
    EXPECT_EQ(s.rise[i], before[i]) << i;
  }
  int warm = 0;
  for (std::size_t k = 0; k < cut.new_vertices.size(); ++k) {
    const tissue::NewVertex& nv = cut.new_vertices[k];
    const std::uint32_t i =
        fascia.first_particle + cut.first_new_vertex + static_cast<std::uint32_t>(k);
    const Real ra = s.rise[fascia.first_particle + nv.a], rb = s.rise[fascia.first_particle + nv.b];
    EXPECT_NEAR(s.rise[i], (1 - nv.t) * ra + nv.t * rb, 1e-15 * (ra + rb)) << k;
    if (nv.a == nv.b) {
      EXPECT_EQ(s.rise[i], ra) << k;
    }
    warm += s.rise[i] > 0 ? 1 : 0;
  }
  EXPECT_EQ(warm, int(cut.new_vertices.size()));  // the whole cut runs through heated tissue
}

TEST(Cautery, TissueCoolsAtTheRateAHotSpotOfTheSourcesWidthConducts) {
  HeatedFascia h;
  tissue::TissueWorld& w = h.patch.world;
  const Real dt = 0.005;
  // tau = sigma^2 / (4 alpha): (1.5 mm)^2 / (4 x 1.4e-7 m^2/s) = 4.018 s.
  EXPECT_NEAR(cooling_time(h.params), 2.25e-6 / 5.6e-7, 1e-9);
  // Coagulate the vertex under the electrode and injure nothing; then the pedal comes up.
  for (int n = 0; n < 400 && !h.state.coagulated[h.v]; ++n)
    apply_cautery(w, h.params, PedalMode::coag, h.a, h.b, dt, h.state);
  ASSERT_TRUE(h.state.coagulated[h.v]);
  const std::vector<Real> hot = h.state.rise;
  // The first step's fall is conduction's initial rate on a Gaussian peak of width sigma,
  // d/dt [sigma^2 / (sigma^2 + 4 alpha t)] at t = 0 = -4 alpha / sigma^2.
  cool_tissue(h.params, dt, h.state);
  const Real sigma = h.params.spread_radius / 2;
  const Real rate = (hot[h.v] - h.state.rise[h.v]) / (hot[h.v] * dt);
  EXPECT_NEAR(rate, 4 * h.params.thermal_diffusivity / (sigma * sigma), 1e-3 * rate);
  // Ten seconds later every rise is its start times exp(-t / tau); the flags stay.
  for (int n = 1; n < 2000; ++n)
    cool_tissue(h.params, dt, h.state);
  const Real left = std::exp(-Real(10) / cooling_time(h.params));
  for (std::size_t i = 0; i < hot.size(); ++i)
    EXPECT_NEAR(h.state.rise[i], hot[i] * left, 1e-9 + 1e-9 * hot[i]) << i;
  EXPECT_GT(h.state.rise[h.v], 0);
  EXPECT_TRUE(h.state.coagulated[h.v]);
  // Without diffusivity nothing cools.
  h.params.thermal_diffusivity = 0;
  const std::vector<Real> kept = h.state.rise;
  cool_tissue(h.params, dt, h.state);
  EXPECT_EQ(h.state.rise, kept);
  h.params.thermal_diffusivity = -1;
  EXPECT_THROW(validate(h.params), std::invalid_argument);
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
