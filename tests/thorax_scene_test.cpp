// The thorax scene: the heart keeps tissue out, drives the field (also the vertices a cut adds to
// the anchored fascia), and the run is deterministic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/edge_adjacency.hpp"
#include "physics/executor.hpp"
#include "scene/thorax_scene.hpp"
#include "surgery/fascia_cut.hpp"
#include "tissue/topology_change.hpp"

namespace imasim::scene {
namespace {

// columns: the vessel's fat as columns (`ima_fat.resists_compression`, tissue/fat_support.hpp).
ThoraxScene make(bool beating, bool columns = false) {
  ThoraxSceneParams p = default_thorax_scene_params();
  p.playback.beating = beating;
  p.patch.ima_fat.resists_compression = columns;
  return make_thorax_scene(p);
}

TEST(ThoraxScene, NoTissueParticleInsideTheHeartAfterSecondsOfBeating) {
  ThoraxScene s = make(true);
  physics::Executor exec(1);
  std::uint64_t contacts = 0;
  for (int n = 0; n < 600; ++n) {  // 3 s, nearly 4 beats
    ASSERT_TRUE(step_thorax_scene(s, exec).ok());
    contacts += s.heart.last_contacts;
    if (n % 50 != 49) continue;
    const physics::Particles& P = s.patch.world.state.particles;
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (P.inverse_mass[i] == 0) continue;
      EXPECT_GE(tissue::heart_signed_distance(s.heart, P.position[i], 0.03), 0.0)
          << "particle " << i << " at step " << n;
    }
  }
  EXPECT_GT(contacts, 1000u);  // the heart did press on the tissue
}

// Largest displacement over the last beat of each IMA particle from its position at that beat's
// start, and the particle's distance from the heart.
std::vector<std::pair<double, double>> ima_motion(bool beating, bool columns = false) {
  ThoraxScene s = make(beating, columns);
  physics::Executor exec(2);
  for (int n = 0; n < 240; ++n)
    EXPECT_TRUE(step_thorax_scene(s, exec).ok());  // 1.5 beats
  const tissue::TissueWorld& w = s.patch.world;
  const tissue::MeshObject& ima = w.meshes[s.patch.ima];
  std::vector<Vec3> start(ima.particle_count);
  for (std::uint32_t k = 0; k < ima.particle_count; ++k)
    start[k] = w.state.particles.position[ima.first_particle + k];
  std::vector<std::pair<double, double>> out(ima.particle_count, {0.0, 0.0});
  for (int n = 0; n < 160; ++n) {  // one beat at 75 bpm
    EXPECT_TRUE(step_thorax_scene(s, exec).ok());
    for (std::uint32_t k = 0; k < ima.particle_count; ++k) {
      out[k].second =
          std::max(out[k].second,
                   double((w.state.particles.position[ima.first_particle + k] - start[k]).norm()));
    }
  }
  for (std::uint32_t k = 0; k < ima.particle_count; ++k) {
    out[k].first = tissue::heart_signed_distance(
        s.heart, w.state.particles.rest_position[ima.first_particle + k], 0.2);
  }
  return out;
}

// Mean motion over a beat of the third of the IMA's particles nearest the heart (first) and of
// the third farthest from it (second).
std::pair<double, double> near_and_far_motion(std::vector<std::pair<double, double>> motion) {
  std::sort(motion.begin(), motion.end());  // by distance from the heart
  const std::size_t third = motion.size() / 3;
  double near = 0, far = 0;
  for (std::size_t k = 0; k < third; ++k)
    near += motion[k].second / double(third);
  for (std::size_t k = motion.size() - third; k < motion.size(); ++k)
    far += motion[k].second / double(third);
  return {near, far};
}

TEST(ThoraxScene, HeartMotionReachesTheImaAndFallsWithDistance) {
  const auto [near, far] = near_and_far_motion(ima_motion(true));
  EXPECT_GT(near, 5e-4);       // sub-millimetre to millimetres of motion near the heart
  EXPECT_GT(near, 1.5 * far);  // less far from it
  EXPECT_GT(far, 0.0);
}

// The fat's columns hold the vessel where the heart's drive puts it (its reference), not at its
// rest: it moves over a beat as it does without them, within 10 %.
TEST(ThoraxScene, TheFatsColumnsHoldTheVesselWhereTheHeartsDrivePutsIt) {
  const double free = near_and_far_motion(ima_motion(true)).first;
  const double held = near_and_far_motion(ima_motion(true, true)).first;
  EXPECT_GT(free, 5e-4);
  EXPECT_NEAR(held, free, 0.1 * free);
}

TEST(ThoraxScene, StaticHeartTransmitsNoMotion) {
  // Zero to rounding: what moves is rounding noise of the solver, relaxing by 0.8 a step.
  for (const auto& [distance, amplitude] : ima_motion(false)) {
    EXPECT_LT(amplitude, 1e-15);
  }
}

// The heart anchor of particle i, if it has one (a scan: the test does not rely on any index).
const tissue::HeartField::Anchor* anchor_of(const tissue::HeartField& h, std::uint32_t i) {
  for (const tissue::HeartField::Anchor& a : h.anchors)
    if (a.particle == i) return &a;
  return nullptr;
}

// Each anchored particle follows the heart vertex nearest its rest position (a scan of all of
// them here), with the weight exp(-d / L) of that distance. Particles farther from the heart's
// box than the first search box once took a nearer-looking vertex of the grid's border cells.
TEST(ThoraxScene, EachAnchorFollowsTheNearestHeartVertex) {
  const ThoraxScene s = make(false);
  const tissue::HeartField& h = s.heart;
  const physics::Particles& P = s.patch.world.state.particles;
  ASSERT_GT(h.anchors.size(), 1000u);
  int wrong = 0;
  for (const tissue::HeartField::Anchor& a : h.anchors) {
    const Vec3& x = P.rest_position[a.particle];
    std::uint32_t nearest = 0;
    Real nearest_d2 = std::numeric_limits<Real>::infinity();
    for (std::uint32_t v = 0; v < h.reference.size(); ++v) {
      const Real d2 = (h.reference[v] - x).squaredNorm();
      if (d2 < nearest_d2) nearest_d2 = d2, nearest = v;
    }
    const Real chosen_d2 = (h.reference[a.heart_vertex] - x).squaredNorm();
    if (chosen_d2 != nearest_d2 && wrong++ < 5) {
      ADD_FAILURE() << "particle " << a.particle << ": heart vertex " << a.heart_vertex << " at "
                    << std::sqrt(chosen_d2) << " m, vertex " << nearest << " at "
                    << std::sqrt(nearest_d2) << " m";
    }
    EXPECT_NEAR(a.weight, std::exp(-std::sqrt(nearest_d2) / h.attenuation_length), 1e-12);
  }
  EXPECT_EQ(wrong, 0) << "anchors not at their nearest heart vertex";
}

TEST(ThoraxScene, VerticesCutIntoTheFasciasFixedPerimeterMoveWithTheHeart) {
  ThoraxScene s = make(true);
  tissue::TissueWorld& w = s.patch.world;
  physics::Particles& P = w.state.particles;
  physics::Executor exec(1);
  for (int n = 0; n < 20; ++n)
    ASSERT_TRUE(step_thorax_scene(s, exec).ok());
  const tissue::MeshObject& fascia = w.meshes[s.patch.fascia];
  const std::uint32_t first = fascia.first_particle;
  // A perimeter edge (boundary, both ends fixed) in the middle of the sheet's first long side.
  const geometry::EdgeAdjacency adj = geometry::build_edge_adjacency(tissue::rest_mesh(w, fascia));
  const geometry::MeshEdge* edge = nullptr;
  for (const geometry::MeshEdge& e : adj.edges) {
    if (e.is_interior() || !P.is_fixed(first + e.a) || !P.is_fixed(first + e.b)) continue;
    if (e.a / 12 != 20 && e.b / 12 != 20) continue;  // row 20 of 40
    if (e.a % 12 == 0 && e.b % 12 == 0) edge = &e;   // column 0: along the long side
  }
  ASSERT_NE(edge, nullptr);
  const Vec3 xa = P.position[first + edge->a], xb = P.position[first + edge->b];
  const Vec3 inside = P.position[first + edge->opposite[0]];
  const Vec3 along = (xb - xa).normalized();
  const Vec3 normal = fascia.normals[edge->a].normalized();
  Vec3 across = normal.cross(along).normalized();  // in the sheet, across the edge
  if (across.dot(inside - xa) < 0) across = -across;
  // The blade across the sheet, swept from 2 mm outside the edge to 2 mm inside it.
  const Vec3 middle = (xa + xb) / 2;
  const surgery::CuttingGeometry g{middle - Real(0.003) * normal - Real(0.002) * across,
                                   Real(0.006) * normal, Real(0.004) * across};
  surgery::FasciaCutter cutter = surgery::make_fascia_cutter(s.patch.fascia);
  const surgery::FasciaCutResult cut = surgery::cut_fascia(w, {}, g, cutter);
  ASSERT_EQ(cut.status, tissue::EditStatus::applied);
  ASSERT_EQ(cut.first_new_vertex + cut.new_vertices.size(), fascia.particle_count);
  tissue::anchor_new_vertices(s.heart, w, s.patch.fascia, cut.first_new_vertex, cut.new_vertices);
  // Each new vertex's anchor, from its parents' (set-up anchors, or those expected for new
  // parents, made earlier): the nearer parent's heart vertex, the weight interpolated like the
  // position.
  struct Expected {
    std::uint32_t particle, heart_vertex;
    Real weight;
    Vec3 at_cut;
  };
  std::vector<Expected> expected;
  auto parent = [&](std::uint32_t v) -> std::pair<std::uint32_t, Real> {
    if (v >= cut.first_new_vertex) {
      const Expected& e = expected[v - cut.first_new_vertex];
      return {e.heart_vertex, e.weight};
    }
    const tissue::HeartField::Anchor* a = anchor_of(s.heart, first + v);
    EXPECT_NE(a, nullptr) << "fascia vertex " << v;
    return a ? std::pair{a->heart_vertex, a->weight} : std::pair{0u, Real(0)};
  };
  std::uint32_t fixed = 0;
  for (std::size_t k = 0; k < cut.new_vertices.size(); ++k) {
    const tissue::NewVertex& nv = cut.new_vertices[k];
    const std::uint32_t i = first + cut.first_new_vertex + static_cast<std::uint32_t>(k);
    const auto [ha, wa] = parent(nv.a);
    const auto [hb, wb] = parent(nv.b);
    expected.push_back(
        {i, nv.t <= Real(0.5) ? ha : hb, (1 - nv.t) * wa + nv.t * wb, P.position[i]});
    const tissue::HeartField::Anchor* anchor = anchor_of(s.heart, i);
    EXPECT_NE(anchor, nullptr) << "new vertex " << k;
    if (anchor) {
      EXPECT_EQ(anchor->heart_vertex, expected.back().heart_vertex);
      EXPECT_EQ(anchor->weight, expected.back().weight);
    }
    fixed += P.is_fixed(i) ? 1 : 0;
  }
  ASSERT_GE(fixed, 1u);  // the vertex made on the perimeter edge (and any copy of it)
  // Over the next 60 steps (about 3/4 of a beat) they go where their anchors drive them.
  Real travelled = 0;
  for (int n = 0; n < 60; ++n) {
    ASSERT_TRUE(step_thorax_scene(s, exec).ok());
    const tissue::HeartField& h = s.heart;
    for (const Expected& e : expected) {
      const Vec3 drive = e.weight * (h.current[e.heart_vertex] - h.reference[e.heart_vertex]);
      EXPECT_NEAR((w.reference[e.particle] - (P.rest_position[e.particle] + drive)).norm(), 0,
                  1e-15);
      if (!P.is_fixed(e.particle)) continue;
      EXPECT_NEAR((P.position[e.particle] - (P.rest_position[e.particle] + drive)).norm(), 0,
                  1e-15);
      travelled = std::max(travelled, (P.position[e.particle] - e.at_cut).norm());
    }
  }
  EXPECT_GT(travelled, Real(1e-4));  // they did move with the beating heart
}

TEST(ThoraxScene, DeterministicAcrossThreadCountsAndHasItsPorts) {
  std::uint64_t hash[3];
  for (int t = 0; t < 3; ++t) {
    ThoraxScene s = make(true);
    physics::Executor exec(t == 2 ? 4 : t + 1);
    for (int n = 0; n < 60; ++n)
      ASSERT_TRUE(step_thorax_scene(s, exec).ok());
    hash[t] = physics::position_hash(s.patch.world.state);
    ASSERT_EQ(s.ports.size(), 4u);
    EXPECT_EQ(s.ports[0].kind, PortKind::camera);
    for (const Port& p : s.ports)
      EXPECT_NEAR(p.direction.norm(), 1.0, 1e-12);
  }
  EXPECT_EQ(hash[0], hash[1]);
  EXPECT_EQ(hash[0], hash[2]);
}

}  // namespace
}  // namespace imasim::scene
