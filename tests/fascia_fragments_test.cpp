// Removing triangles from a mesh object (tissue::remove_mesh_triangles) and the small free pieces
// a cut leaves (surgery::vaporise_free_fragments): every invariant holds after the change,
// indices to the survivors are renumbered, bindings keep their rest point, and only what nothing
// holds goes.
#include "surgery/fascia_fragments.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "geometry/closest_point.hpp"
#include "geometry/grid_rectangle.hpp"
#include "geometry/surface_binding.hpp"
#include "physics/state.hpp"
#include "tissue/mesh_object.hpp"
#include "tissue/tissue_step.hpp"

namespace imasim::surgery {
namespace {

using geometry::SurfaceBinding;
using geometry::Triangle;

// A 2 x 2-cell sheet, 2 cm square, in the x-z plane: triangles 0 and 1 are the cell at the
// origin, the only two that use vertex 0.
tissue::TissueWorld small_sheet() {
  tissue::TissueWorld w;
  tissue::MeshObjectParams p;
  p.name = "sheet";
  p.total_mass = 0.009;
  p.spare_vertices = 4;
  tissue::add_mesh_object(w, geometry::make_grid_rectangle({0.02, 0.02, 3, 3}), p);
  tissue::finish_setup(w);
  return w;
}

Vec3 rest_point(const tissue::TissueWorld& w, const tissue::MeshObject& m,
                const SurfaceBinding& b) {
  const Triangle& t = m.triangles[b.triangle];
  const auto& rest = w.state.particles.rest_position;
  return b.bary[0] * rest[m.first_particle + t[0]] + b.bary[1] * rest[m.first_particle + t[1]] +
         b.bary[2] * rest[m.first_particle + t[2]];
}

Vec3 point_now(const tissue::TissueWorld& w, const tissue::MeshObject& m, const SurfaceBinding& b) {
  const Triangle& t = m.triangles[b.triangle];
  const auto& x = w.state.particles.position;
  return b.bary[0] * x[m.first_particle + t[0]] + b.bary[1] * x[m.first_particle + t[1]] +
         b.bary[2] * x[m.first_particle + t[2]];
}

TEST(TopologyChange, RemovingTrianglesRetiresTheirVerticesAndRenumbersTheRest) {
  tissue::TissueWorld w = small_sheet();
  tissue::MeshObject& m = w.meshes[0];
  physics::Particles& P = w.state.particles;
  ASSERT_EQ(m.triangles.size(), 8u);
  const std::vector<Triangle> before = m.triangles;
  for (std::uint32_t v = 0; v < m.particle_count; ++v) {
    P.velocity[v] = Vec3(0, 0.01 * v, 0);
    P.position[v] += Vec3(0, 0.002 * (v % 3), 0);  // bent: nearest now differs from at rest
  }
  // A visual mesh bound to a surviving triangle after the removed ones, and to a removed one.
  tissue::VisualMesh visual;
  visual.source_mesh = 0;
  visual.bindings = {{5, {0.2, 0.3, 0.5}, 0}, {0, {0.1, 0.1, 0.8}, 0}};
  visual.positions.resize(visual.bindings.size());
  w.visuals.push_back(visual);
  const Vec3 kept_point = rest_point(w, m, w.visuals[0].bindings[0]);
  const Vec3 lost_point = point_now(w, m, w.visuals[0].bindings[1]);
  // Vertex 0 drove a particle of the sheet through a coupling; vertex 4 another.
  w.couplings.push_back({"test", {{0, 8}, {4, 2}}, Real(0.01), tissue::Beta::one, Real(0.8)});
  const std::size_t distance_before = w.state.constraints.distance.size();
  const std::size_t dihedral_before = w.state.constraints.dihedral.size();

  const std::uint32_t removed[] = {1, 0};
  const tissue::TopologyChange c = tissue::remove_mesh_triangles(w, 0, removed);
  ASSERT_EQ(c.status, tissue::EditStatus::applied) << c.message;
  EXPECT_EQ(tissue::first_topology_defect(w, 0, {}), "");
  // The survivors keep their order.
  ASSERT_EQ(m.triangles.size(), 6u);
  for (std::size_t f = 0; f < 6; ++f)
    EXPECT_EQ(m.triangles[f], before[f + 2]);
  // Vertex 0 is retired: fixed and at rest; the others keep their mass and motion.
  EXPECT_TRUE(P.is_fixed(0));
  EXPECT_EQ(P.velocity[0], Vec3::Zero());
  for (std::uint32_t v = 1; v < m.particle_count; ++v) {
    EXPECT_FALSE(P.is_fixed(v)) << v;
    EXPECT_EQ(P.velocity[v], Vec3(0, 0.01 * v, 0));
  }
  // Edges (0,1), (0,3), (0,4) went; (1,4) and (3,4) are boundary edges now: no dihedral.
  for (std::uint32_t v : {1u, 3u, 4u})
    EXPECT_EQ(m.edges.count(tissue::edge_key(0, v)), 0u);
  for (std::uint32_t v : {1u, 3u}) {
    const tissue::EdgeRecord& r = m.edges.at(tissue::edge_key(v, 4));
    EXPECT_TRUE(w.state.constraints.distance.resolves(r.distance));
    EXPECT_FALSE(w.state.constraints.dihedral.resolves(r.dihedral));
  }
  EXPECT_EQ(w.state.constraints.distance.size(), distance_before - 3);
  EXPECT_EQ(w.state.constraints.dihedral.size(), dihedral_before - 3);  // (0,4), (1,4), (3,4)
  // The binding on a survivor moved with its triangle's new index, to the same rest point; the
  // one on a removed triangle went to the nearest point of a survivor where they are now.
  const SurfaceBinding& kept = w.visuals[0].bindings[0];
  EXPECT_EQ(kept.triangle, 3u);
  EXPECT_LT((rest_point(w, m, kept) - kept_point).norm(), 1e-15);
  const SurfaceBinding& lost = w.visuals[0].bindings[1];
  ASSERT_LT(lost.triangle, 6u);
  Real nearest = std::numeric_limits<Real>::infinity();
  for (const Triangle& t : m.triangles) {
    const auto& x = P.position;
    nearest = std::min(
        nearest,
        geometry::closest_point_on_triangle(lost_point, x[t[0]], x[t[1]], x[t[2]]).distance2);
  }
  EXPECT_NEAR((point_now(w, m, lost) - lost_point).squaredNorm(), nearest, 1e-18);
  EXPECT_GT(nearest, 0);
  // What vertex 0 drove is no longer driven by it; vertex 4's pair stays.
  ASSERT_EQ(w.couplings[0].pairs.size(), 1u);
  EXPECT_EQ(w.couplings[0].pairs[0], std::make_pair(4u, 2u));
  // The sheet still steps.
  physics::Executor exec(1);
  EXPECT_TRUE(tissue::step_tissue(w, exec).ok());
  EXPECT_EQ(tissue::first_topology_defect(w, 0, {}), "");
}

TEST(TopologyChange, RefusedRemovalsLeaveTheWorldAsItWas) {
  auto expect_refused = [](tissue::TissueWorld& w, std::initializer_list<std::uint32_t> faces,
                           const std::string& why) {
    const std::uint64_t hash = physics::position_hash(w.state);
    const std::size_t distance = w.state.constraints.distance.size();
    const std::vector<Triangle> triangles = w.meshes[0].triangles;
    const std::vector<std::uint32_t> list(faces);
    const tissue::TopologyChange c = tissue::remove_mesh_triangles(w, 0, list);
    EXPECT_EQ(c.status, tissue::EditStatus::invalid);
    EXPECT_NE(c.message.find(why), std::string::npos) << c.message;
    EXPECT_EQ(physics::position_hash(w.state), hash);
    EXPECT_EQ(w.state.constraints.distance.size(), distance);
    EXPECT_EQ(w.meshes[0].triangles, triangles);
    EXPECT_FALSE(w.state.particles.is_fixed(0));
  };
  tissue::TissueWorld w = small_sheet();
  expect_refused(w, {0, 8}, "does not exist");
  expect_refused(w, {0, 1, 2, 3, 4, 5, 6, 7}, "every triangle");
  w.held[0] = 1;  // the forceps hold vertex 0
  expect_refused(w, {0, 1}, "held by an instrument");
  w.held[0] = 0;
  w.couplings.push_back({"drives vertex 0", {{4, 0}}, Real(0.01), tissue::Beta::one, Real(0.8)});
  expect_refused(w, {0, 1}, "moved by coupling drives vertex 0");
  EXPECT_EQ(tissue::first_topology_defect(w, 0, {}), "");
}

// One mesh object of two pieces: a 4 cm sheet (5 x 5 vertices, its perimeter fixed) and beside
// it a free `piece` (its vertices from 25 on).
tissue::TissueWorld sheet_and(const geometry::TriangleMesh& piece) {
  geometry::TriangleMesh mesh = geometry::make_grid_rectangle({0.04, 0.04, 5, 5});
  const auto offset = static_cast<std::uint32_t>(mesh.vertices.size());
  for (const Vec3& x : piece.vertices)
    mesh.vertices.push_back(x + Vec3(0.05, 0, 0.01));
  for (const Triangle& t : piece.triangles)
    mesh.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
  tissue::TissueWorld w;
  tissue::MeshObjectParams p;
  p.name = "fascia";
  p.total_mass = 0.01;
  p.spare_vertices = 8;
  tissue::add_mesh_object(w, mesh, p);
  physics::Particles& P = w.state.particles;
  for (std::uint32_t v = 0; v < 25; ++v) {
    const std::uint32_t i = v % 5, j = v / 5;
    if (i == 0 || i == 4 || j == 0 || j == 4) P.inverse_mass[v] = 0;
  }
  tissue::finish_setup(w);
  return w;
}

// The sheet and a free square of side `side` (two triangles, vertices 25-28).
tissue::TissueWorld sheet_and_square(Real side) {
  return sheet_and(geometry::make_grid_rectangle({side, side, 2, 2}));
}

TEST(FasciaFragments, ASmallFreePieceIsVaporisedAndTheSheetStays) {
  tissue::TissueWorld w = sheet_and_square(0.002);  // 4 mm^2
  FasciaCutter cutter = make_fascia_cutter(0);
  // The cutter had reached the square: its diagonal edge and two of its vertices.
  cutter.pending = {tissue::edge_key(25, 28)};
  cutter.cut_vertices = {12, 25, 28};
  const std::vector<Vec3> sheet_before(w.state.particles.position.begin(),
                                       w.state.particles.position.begin() + 25);
  const FragmentRemoval r = vaporise_free_fragments(w, FragmentParams{}, cutter);
  EXPECT_EQ(r.status, tissue::EditStatus::applied);
  EXPECT_EQ(r.fragments, 1u);
  EXPECT_EQ(r.triangles, 2u);
  EXPECT_NEAR(r.area, 4e-6, 1e-15);
  const tissue::MeshObject& m = w.meshes[0];
  EXPECT_EQ(m.triangles.size(), 32u);
  for (const Triangle& t : m.triangles)
    for (std::uint32_t v : t)
      EXPECT_LT(v, 25u);
  for (std::uint32_t v = 25; v < 29; ++v)
    EXPECT_TRUE(w.state.particles.is_fixed(v));
  EXPECT_TRUE(
      std::equal(sheet_before.begin(), sheet_before.end(), w.state.particles.position.begin()));
  EXPECT_TRUE(cutter.pending.empty());
  EXPECT_EQ(cutter.cut_vertices, std::vector<std::uint32_t>{12});
  EXPECT_EQ(tissue::first_topology_defect(w, 0, {}), "");
  // Nothing more to take.
  EXPECT_EQ(vaporise_free_fragments(w, FragmentParams{}, cutter).fragments, 0u);
}

TEST(FasciaFragments, WhatIsLargeFixedHeldOrDrivenStays) {
  auto pieces_taken = [](tissue::TissueWorld& w, FragmentParams params = {}) {
    FasciaCutter cutter = make_fascia_cutter(0);
    const std::size_t before = w.meshes[0].triangles.size();
    const std::uint32_t taken = vaporise_free_fragments(w, params, cutter).fragments;
    EXPECT_EQ(w.meshes[0].triangles.size(), before - 2 * taken);
    return taken;
  };
  {  // larger than the limit: 4 mm^2 against 3 mm^2
    tissue::TissueWorld w = sheet_and_square(0.002);
    FragmentParams small;
    small.max_area = 3e-6;
    EXPECT_EQ(pieces_taken(w, small), 0u);
  }
  {  // one vertex fixed
    tissue::TissueWorld w = sheet_and_square(0.002);
    w.state.particles.inverse_mass[27] = 0;
    EXPECT_EQ(pieces_taken(w), 0u);
  }
  {  // in the forceps
    tissue::TissueWorld w = sheet_and_square(0.002);
    w.held[26] = 1;
    EXPECT_EQ(pieces_taken(w), 0u);
  }
  {  // a coupling moves it after the sheet
    tissue::TissueWorld w = sheet_and_square(0.002);
    w.couplings.push_back({"sheet->square", {{12, 26}}, Real(0.01), tissue::Beta::one, Real(0.8)});
    EXPECT_EQ(pieces_taken(w), 0u);
  }
  {  // a coupling from it moves the sheet: it holds nothing, so it goes, and the pair with it
    tissue::TissueWorld w = sheet_and_square(0.002);
    w.couplings.push_back(
        {"square->sheet", {{26, 12}, {6, 12}}, Real(0.01), tissue::Beta::one, Real(0.8)});
    EXPECT_EQ(pieces_taken(w), 1u);
    ASSERT_EQ(w.couplings[0].pairs.size(), 1u);
    EXPECT_EQ(w.couplings[0].pairs[0].first, 6u);
  }
  {  // the sheet is never taken, however small
    tissue::TissueWorld w = sheet_and_square(0.002);
    FragmentParams huge;
    huge.max_area = 1;
    EXPECT_EQ(pieces_taken(w, huge), 1u);
    EXPECT_EQ(w.meshes[0].triangles.size(), 32u);
  }
}

TEST(FasciaFragments, APieceHeldThroughAnyCornerOfItsTrianglesStays) {
  // One 2 mm^2 triangle listed highest corner first, (27, 25, 26), held only by its second
  // corner: a union-find that joined each corner to the first corner's root as found before the
  // first join split corner 25 off, and took the triangle as free.
  geometry::TriangleMesh triangle;
  triangle.vertices = {Vec3(0, 0, 0), Vec3(0.002, 0, 0), Vec3(0, 0, 0.002)};
  triangle.triangles = {{2, 0, 1}};
  for (const std::uint32_t held_corner : {25u, 26u, 27u}) {
    tissue::TissueWorld w = sheet_and(triangle);
    w.state.particles.inverse_mass[held_corner] = 0;
    FasciaCutter cutter = make_fascia_cutter(0);
    EXPECT_EQ(vaporise_free_fragments(w, FragmentParams{}, cutter).fragments, 0u) << held_corner;
    EXPECT_EQ(w.meshes[0].triangles.size(), 33u);
  }
  tissue::TissueWorld w = sheet_and(triangle);  // and free, it goes
  FasciaCutter cutter = make_fascia_cutter(0);
  EXPECT_EQ(vaporise_free_fragments(w, FragmentParams{}, cutter).fragments, 1u);
  EXPECT_EQ(w.meshes[0].triangles.size(), 32u);
}

}  // namespace
}  // namespace imasim::surgery
