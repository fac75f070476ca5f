// Fascia cutting (2.4.1): one topology-change API keeps the mesh, constraints, colouring,
// masses, couplings and bindings consistent; a cut along the tool's path over many steps opens
// the fascia along it; 10,000 random cuts keep every invariant.
#include "surgery/fascia_cut.hpp"
#include "surgery/fascia_fragments.hpp"

#include <gtest/gtest.h>

#include <random>

#include "geometry/edge_adjacency.hpp"
#include "geometry/grid_rectangle.hpp"
#include "physics/executor.hpp"
#include "tissue/mesh_object.hpp"
#include "tissue/thoracic_patch.hpp"
#include "tissue/tissue_step.hpp"

namespace imasim::surgery {
namespace {

geometry::MeshCheckOptions cut_checks(const FasciaCutParams& p) {
  geometry::MeshCheckOptions o;
  // Every piece a cut makes is at least this good; the grid's own triangles are better.
  o.min_angle = p.min_angle * Real(1 - 1e-12);
  o.min_area = p.min_area * Real(1 - 1e-12);
  return o;
}

// A 2 x 2-cell sheet in the x-z plane with spare vertices, for exact checks of one edit.
tissue::TissueWorld small_sheet() {
  tissue::TissueWorld w;
  geometry::TriangleMesh mesh = geometry::make_grid_rectangle({0.02, 0.02, 3, 3});
  tissue::MeshObjectParams p;
  p.name = "sheet";
  p.total_mass = 0.009;
  p.spare_vertices = 8;
  tissue::add_mesh_object(w, mesh, p);
  tissue::finish_setup(w);
  return w;
}

TEST(TopologyChange, SplittingAnEdgeInterpolatesAndRebuildsItsConstraints) {
  tissue::TissueWorld w = small_sheet();
  tissue::MeshObject& m = w.meshes[0];
  physics::Particles& P = w.state.particles;
  for (std::uint32_t v = 0; v < m.particle_count; ++v) {
    P.position[v] += Vec3(0, 0.001 * v, 0);
    P.velocity[v] = Vec3(v, 2.0 * v, -1.0 * v);
  }
  // Split edge (a, b) shared by triangles f and g at t = 0.25.
  const geometry::EdgeAdjacency adj = geometry::build_edge_adjacency(tissue::rest_mesh(w, m));
  const geometry::MeshEdge* edge = nullptr;
  for (const auto& e : adj.edges)
    if (e.is_interior() && !edge) edge = &e;
  ASSERT_NE(edge, nullptr);
  const std::uint32_t a = edge->a, b = edge->b, n = m.particle_count;
  const physics::DistanceHandle old_distance = m.edges.at(tissue::edge_key(a, b)).distance;
  const physics::DihedralHandle old_dihedral = m.edges.at(tissue::edge_key(a, b)).dihedral;
  tissue::MeshEdit edit;
  edit.vertices.push_back({a, b, 0.25});
  for (int k = 0; k < 2; ++k) {
    const std::uint32_t f = edge->faces[k], o = edge->opposite[k];
    const bool forward = k == 0;  // faces[0] runs a -> b
    const std::uint32_t from = forward ? a : b, to = forward ? b : a;
    edit.replaced.emplace_back(f, geometry::Triangle{from, n, o});
    edit.added.push_back({geometry::Triangle{n, to, o}, f});
  }
  const std::size_t distance_before = w.state.constraints.distance.size();
  const tissue::TopologyChange c = tissue::apply_mesh_edit(w, 0, edit);
  ASSERT_EQ(c.status, tissue::EditStatus::applied) << c.message;
  const std::uint32_t i = m.first_particle + n;
  EXPECT_EQ(m.particle_count, n + 1);
  // Current, rest and velocity: (1 - t) x_a + t x_b.
  EXPECT_EQ(P.position[i], Real(0.75) * P.position[a] + Real(0.25) * P.position[b]);
  EXPECT_EQ(P.rest_position[i], Real(0.75) * P.rest_position[a] + Real(0.25) * P.rest_position[b]);
  EXPECT_EQ(P.velocity[i], Real(0.75) * P.velocity[a] + Real(0.25) * P.velocity[b]);
  // The split edge's constraints are gone; its halves have rest lengths t L and (1 - t) L.
  EXPECT_FALSE(w.state.constraints.distance.resolves(old_distance));
  EXPECT_FALSE(w.state.constraints.dihedral.resolves(old_dihedral));
  const Real length = (P.rest_position[a] - P.rest_position[b]).norm();
  const auto* half_a =
      w.state.constraints.distance.find(m.edges.at(tissue::edge_key(a, n)).distance);
  const auto* half_b =
      w.state.constraints.distance.find(m.edges.at(tissue::edge_key(n, b)).distance);
  ASSERT_TRUE(half_a && half_b);
  EXPECT_NEAR(half_a->rest_length, 0.25 * length, 1e-15);
  EXPECT_NEAR(half_b->rest_length, 0.75 * length, 1e-15);
  // Two triangles became four: one more interior edge on each side plus the two halves.
  EXPECT_EQ(w.state.constraints.distance.size(), distance_before + 3);
  EXPECT_EQ(c.distance_removed.size() + 3, c.distance_added.size());
  // eq. 5 with the new count, and every invariant.
  EXPECT_EQ(tissue::first_topology_defect(w, 0, {}), "");
}

TEST(TopologyChange, RefusedEditsLeaveTheWorldAsItWas) {
  tissue::TissueWorld w = small_sheet();
  const std::uint64_t hash = physics::position_hash(w.state);
  const std::size_t constraints = w.state.constraints.distance.size();
  tissue::MeshEdit bad;
  bad.vertices.push_back({0, 99, 0.5});
  EXPECT_EQ(tissue::apply_mesh_edit(w, 0, bad).status, tissue::EditStatus::invalid);
  tissue::MeshEdit too_many;
  for (int k = 0; k < 9; ++k)
    too_many.vertices.push_back({0, 1, 0.5});
  EXPECT_EQ(tissue::apply_mesh_edit(w, 0, too_many).status, tissue::EditStatus::out_of_capacity);
  EXPECT_EQ(physics::position_hash(w.state), hash);
  EXPECT_EQ(w.state.constraints.distance.size(), constraints);
  EXPECT_EQ(w.meshes[0].particle_count, 9u);
}

// Boundary edges of the fascia's rest mesh that are not on its original perimeter.
Real new_boundary_length(const tissue::TissueWorld& w, const tissue::MeshObject& m,
                         const tissue::FasciaParams& f) {
  const geometry::EdgeAdjacency adj = geometry::build_edge_adjacency(tissue::rest_mesh(w, m));
  const Pose inverse{f.pose.rotation.transpose(),
                     -(f.pose.rotation.transpose() * f.pose.translation)};
  auto on_perimeter = [&](const Vec3& x) {
    const Vec3 r = inverse.apply(x);
    return std::abs(r.x()) < 1e-9 || std::abs(r.x() - f.width) < 1e-9 || std::abs(r.z()) < 1e-9 ||
           std::abs(r.z() - f.height) < 1e-9;
  };
  Real length = 0;
  for (const auto& e : adj.edges) {
    if (e.is_interior()) continue;
    const Vec3 a = w.state.particles.rest_position[m.first_particle + e.a];
    const Vec3 b = w.state.particles.rest_position[m.first_particle + e.b];
    if (on_perimeter(a) && on_perimeter(b)) continue;
    length += (a - b).norm();
  }
  return length;
}

TEST(FasciaCut, ABladeDrawnAlongTheVesselOpensTheFasciaAlongItsPath) {
  tissue::ThoracicPatchParams params = tissue::default_thoracic_patch_params();
  tissue::ThoracicPatch patch = tissue::make_thoracic_patch(params);
  tissue::TissueWorld& w = patch.world;
  physics::Executor exec(1);
  const FasciaCutParams cut_params;
  FasciaCutter cutter = make_fascia_cutter(patch.fascia);
  // Strand ends on the fascia, at rest, before cutting: rebinding must keep them in place.
  const tissue::StrandSet& fat = w.strands[patch.fascia_fat];
  auto rest_end = [&](std::uint32_t s) {
    const tissue::MeshObject& m = w.meshes[patch.fascia];
    const geometry::SurfaceBinding& b = fat.end_a[s];
    const geometry::Triangle& t = m.triangles[b.triangle];
    Vec3 x = Vec3::Zero();
    for (int k = 0; k < 3; ++k)
      x += b.bary[k] * w.state.particles.rest_position[m.first_particle + t[k]];
    return x;
  };
  std::vector<Vec3> ends;
  for (std::uint32_t s = 0; s < fat.strand_count; ++s)
    ends.push_back(rest_end(s));
  for (int n = 0; n < 60; ++n)
    ASSERT_TRUE(tissue::step_tissue(w, exec).ok());
  // A blade 30 mm long across the sagging sheet at x = 0.5 mm, drawn 1 mm per step from z = 30
  // to z = 70 mm: continuous cutting over 40 steps, the tissue moving between them.
  const Real x = 0.0005, z0 = 0.03, z1 = 0.07, dz = 0.001;
  std::uint32_t copies = 0;
  for (Real z = z0; z < z1 - dz / 2; z += dz) {
    const CuttingGeometry g{Vec3(x, -0.03, z), Vec3(0, 0.03, 0), Vec3(0, 0, dz)};
    const FasciaCutResult r = cut_fascia(w, cut_params, g, cutter);
    ASSERT_EQ(r.status, tissue::EditStatus::applied);
    copies += r.vertices_copied;
    ASSERT_EQ(tissue::first_topology_defect(w, patch.fascia, cut_checks(cut_params)), "");
    ASSERT_TRUE(tissue::step_tissue(w, exec).ok());
  }
  EXPECT_GT(copies, 8u);
  const tissue::MeshObject& m = w.meshes[patch.fascia];
  // The cut's two lips: about twice the 40 mm path, give or take a cell (3.8 mm) at each end.
  const Real lips = new_boundary_length(w, m, params.fascia);
  EXPECT_GT(lips, 2 * (z1 - z0 - 2 * 0.0038));
  EXPECT_LT(lips, 2 * (z1 - z0 + 2 * 0.0038) * 1.2);
  // No edge joins the sides across the path any more: an edge between rest points on opposite
  // sides of x (beyond epsilon) crosses x outside [z0 + cell, z1 - cell].
  const geometry::EdgeAdjacency adj = geometry::build_edge_adjacency(tissue::rest_mesh(w, m));
  for (const auto& e : adj.edges) {
    const Vec3 a = w.state.particles.rest_position[m.first_particle + e.a];
    const Vec3 b = w.state.particles.rest_position[m.first_particle + e.b];
    const Real da = a.x() - x, db = b.x() - x;
    if (!(da * db < 0) || std::abs(da) < cut_params.proximity ||
        std::abs(db) < cut_params.proximity) {
      continue;
    }
    const Real zc = a.z() + (b.z() - a.z()) * da / (da - db);
    EXPECT_FALSE(zc > z0 + 0.004 && zc < z1 - 0.004) << "edge still joins the sides at z = " << zc;
  }
  // The strand ends on the fascia were re-bound where they were.
  for (std::uint32_t s = 0; s < fat.strand_count; ++s)
    EXPECT_LT((rest_end(s) - ends[s]).norm(), 1e-12) << "strand " << s;
  // And the opened fascia keeps simulating.
  for (int n = 0; n < 100; ++n)
    ASSERT_TRUE(tissue::step_tissue(w, exec).ok());
  EXPECT_EQ(tissue::first_topology_defect(w, patch.fascia, cut_checks(cut_params)), "");
}

// Random cutting geometry over the fascia: anywhere on it, any orientation.
CuttingGeometry random_cut(std::mt19937_64& rng, const tissue::FasciaParams& f) {
  std::uniform_real_distribution<Real> unit(0, 1), sym(-1, 1);
  const Vec3 local(unit(rng) * f.width, sym(rng) * 0.004, unit(rng) * f.height);
  auto direction = [&] {
    Vec3 d(sym(rng), sym(rng), sym(rng));
    while (d.norm() < 0.1)
      d = Vec3(sym(rng), sym(rng), sym(rng));
    return d.normalized();
  };
  CuttingGeometry g;
  g.blade = direction() * (0.002 + 0.01 * unit(rng));
  g.motion = direction() * (0.0002 + 0.005 * unit(rng));
  g.origin = f.pose.apply(local) - g.blade / 2;
  return g;
}

// Random cuts (and, with `vaporise`, the small free pieces they leave taken out after each, as
// the session does); `fragments` counts the pieces taken.
std::uint64_t fuzz(int cuts, bool check_each, std::uint64_t seed, std::string& defect,
                   bool vaporise = false, std::uint32_t* fragments = nullptr) {
  tissue::ThoracicPatchParams params = tissue::default_thoracic_patch_params();
  params.fascia.object.spare_vertices = 40000;
  tissue::ThoracicPatch patch = tissue::make_thoracic_patch(params);
  tissue::TissueWorld& w = patch.world;
  physics::Executor exec(1);
  const FasciaCutParams cut_params;
  FasciaCutter cutter = make_fascia_cutter(patch.fascia);
  std::mt19937_64 rng(seed);
  for (int n = 0; n < cuts; ++n) {
    const FasciaCutResult r = cut_fascia(w, cut_params, random_cut(rng, params.fascia), cutter);
    if (r.status != tissue::EditStatus::applied) {
      defect = "cut " + std::to_string(n) + " was refused";
      return 0;
    }
    if (vaporise) {
      const FragmentRemoval gone = vaporise_free_fragments(w, FragmentParams{}, cutter);
      if (gone.status != tissue::EditStatus::applied) {
        defect = "the pieces cut " + std::to_string(n) + " freed could not be removed";
        return 0;
      }
      if (fragments) *fragments += gone.fragments;
    }
    if (check_each || n + 1 == cuts) {
      defect = tissue::first_topology_defect(w, patch.fascia, cut_checks(cut_params));
      if (!defect.empty()) {
        defect = "after cut " + std::to_string(n) + ": " + defect;
        return 0;
      }
    }
    if (n % 25 == 24 && !tissue::step_tissue(w, exec).ok()) {
      defect = "the step failed after cut " + std::to_string(n);
      return 0;
    }
  }
  return physics::position_hash(w.state);
}

#ifdef IMASIM_SANITIZE
constexpr int kFuzzCuts = 1000;  // the sanitized build checks the same code on fewer cuts
#else
constexpr int kFuzzCuts = 10000;
#endif

TEST(FasciaCut, TenThousandRandomCutsKeepEveryInvariant) {
  std::string defect;
  const std::uint64_t hash = fuzz(kFuzzCuts, true, 2026, defect);
  EXPECT_EQ(defect, "");
  EXPECT_NE(hash, 0u);
}

TEST(FasciaCut, RandomCutsWithTheirFreedPiecesVaporisedKeepEveryInvariant) {
  std::string defect;
  std::uint32_t fragments = 0;
  // The same 1,000 cuts in every build, the sanitized one too (its 200 freed no piece): they free
  // 20 pieces in the Release build.
  const std::uint64_t hash = fuzz(1000, true, 2027, defect, true, &fragments);
  EXPECT_EQ(defect, "");
  EXPECT_NE(hash, 0u);
  EXPECT_GT(fragments, 5u);
  std::string again;
  std::uint32_t fragments_again = 0;
  EXPECT_EQ(fuzz(1000, false, 2027, again, true, &fragments_again), hash);
  EXPECT_EQ(fragments_again, fragments);
}

TEST(FasciaCut, CuttingIsDeterministic) {
  std::string d1, d2;
  const std::uint64_t h1 = fuzz(300, false, 7, d1), h2 = fuzz(300, false, 7, d2);
  EXPECT_EQ(d1, "");
  EXPECT_EQ(h1, h2);
}

}  // namespace
}  // namespace imasim::surgery
