// The cavity's floor: a piece of fascia cut free
// beside the heart comes to rest on the floor under the field (the collapsed lung, the
// pericardium) instead of falling across the cavity to its far wall.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "physics/executor.hpp"
#include "scene/thorax_scene.hpp"
#include "tissue/topology_change.hpp"

namespace imasim::scene {
namespace {

struct Fall {
  Real floor_y = 0;
  Real lowest_y = 0;  // of the freed piece at the end (unit: m)
  Real fastest = 0;   // its largest particle speed at the end (unit: m/s)
  std::size_t piece = 0;
};

// Frees a 15 mm square of the fascia's cranial part, away from the heart, and steps the scene
// (static heart) for `seconds`. `floor_gap` sets anatomy.cavity_floor_gap.
Fall free_a_piece_and_let_it_fall(Real floor_gap, double seconds) {
  ThoraxSceneParams params = default_thorax_scene_params();
  params.playback.beating = false;
  params.anatomy.cavity_floor_gap = floor_gap;
  ThoraxScene s = make_thorax_scene(params);
  tissue::TissueWorld& w = s.patch.world;
  physics::Particles& P = w.state.particles;
  physics::Executor exec(1);
  for (int n = 0; n < 40; ++n)
    EXPECT_TRUE(step_thorax_scene(s, exec).ok());
  const tissue::MeshObject& fascia = w.meshes[s.patch.fascia];
  const std::uint32_t first = fascia.first_particle;
  // The default sheet has 12 vertices across and 40 along. The ring of rows 5 and 11 and columns
  // 3 and 9 goes (every triangle touching it): the 5 x 5 vertices inside it, about 15 mm square
  // beside the vessel's cranial end, are a piece nothing holds.
  constexpr std::uint32_t kColumns = 12;
  auto on_ring = [](std::uint32_t v) {
    const std::uint32_t row = v / kColumns, col = v % kColumns;
    const bool rows = row >= 5 && row <= 11, cols = col >= 3 && col <= 9;
    return (rows && (col == 3 || col == 9)) || (cols && (row == 5 || row == 11));
  };
  std::vector<std::uint32_t> ring;
  for (std::uint32_t f = 0; f < fascia.triangles.size(); ++f) {
    const geometry::Triangle& t = fascia.triangles[f];
    if (on_ring(t[0]) || on_ring(t[1]) || on_ring(t[2])) ring.push_back(f);
  }
  EXPECT_EQ(tissue::remove_mesh_triangles(w, s.patch.fascia, ring).status,
            tissue::EditStatus::applied);
  std::vector<std::uint32_t> piece;
  for (std::uint32_t row = 6; row <= 10; ++row)
    for (std::uint32_t col = 4; col <= 8; ++col)
      piece.push_back(first + row * kColumns + col);
  for (int n = 0; n < int(seconds / 0.005); ++n)
    EXPECT_TRUE(step_thorax_scene(s, exec).ok());
  Fall f;
  f.floor_y = s.layout.cavity_floor_y;
  f.piece = piece.size();
  f.lowest_y = std::numeric_limits<Real>::infinity();
  for (std::uint32_t i : piece) {
    f.lowest_y = std::min(f.lowest_y, P.position[i].y());
    f.fastest = std::max(f.fastest, P.velocity[i].norm());
  }
  return f;
}

TEST(CavityFloor, AFreedPieceOfFasciaRestsOnTheFloorInsteadOfFallingAcrossTheCavity) {
  const Fall held = free_a_piece_and_let_it_fall(ThoraxSceneParams{}.anatomy.cavity_floor_gap, 1.5);
  ASSERT_GT(held.piece, 5u);
  // It fell to the floor (2 cm under the lowest tissue) and lies on it, at rest.
  EXPECT_LT(held.lowest_y, held.floor_y + Real(0.003));
  EXPECT_GT(held.lowest_y, held.floor_y - Real(0.0005));
  EXPECT_LT(held.fastest, Real(0.01));
  // Without a floor (one 10 m down) the same piece falls far past where the floor would be.
  const Fall falling = free_a_piece_and_let_it_fall(10, 1.5);
  EXPECT_LT(falling.lowest_y, held.floor_y - Real(0.05));
}

}  // namespace
}  // namespace imasim::scene
