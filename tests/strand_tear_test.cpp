// Strand tearing (tissue/strand_tear.hpp): a strand tears exactly when its ends are more than
// tear_stretch times their rest distance apart, lets go whole and dissolves like a divided one
// without counting as divided; strands on tissue carried far away tear as they pass the limit.
#include "tissue/strand_tear.hpp"

#include <gtest/gtest.h>

#include "physics/executor.hpp"
#include "surgery/strand_cut.hpp"
#include "tissue/strands.hpp"
#include "tissue/thoracic_patch.hpp"
#include "tissue/tissue_step.hpp"

namespace imasim::tissue {
namespace {

// Moves strand `i`'s wall end so that its ends are `stretch` times their rest distance apart,
// along the strand's rest direction (the end is kinematic: nothing moves it back before the
// check).
void stretch_strand(TissueWorld& w, const StrandSet& set, std::uint32_t i, Real stretch) {
  physics::Particles& P = w.state.particles;
  const std::uint32_t a = set.particle(i, 0), b = set.particle(i, set.segments);
  const Vec3 rest = P.rest_position[b] - P.rest_position[a];
  P.position[b] = P.position[a] + stretch * rest;
}

TEST(StrandTear, TearsExactlyPastTheTearStretch) {
  ThoracicPatch patch = make_thoracic_patch(default_thoracic_patch_params());
  TissueWorld& w = patch.world;
  StrandSet& set = w.strands[patch.fascia_fat];
  ASSERT_EQ(set.tear_stretch, Real(3));
  std::vector<StrandTear> torn;
  // At rest nothing tears.
  EXPECT_EQ(tear_overstretched_strands(w, torn), 0u);

  const std::size_t constraints_before = w.state.constraints.distance.size();
  stretch_strand(w, set, 7, Real(2.99));
  EXPECT_EQ(tear_overstretched_strands(w, torn), 0u);
  EXPECT_EQ(set.cut[7], kStrandIntact);
  stretch_strand(w, set, 7, Real(3.01));
  ASSERT_EQ(tear_overstretched_strands(w, torn), 1u);
  ASSERT_EQ(torn.size(), 1u);
  EXPECT_EQ(torn[0].set, patch.fascia_fat);
  EXPECT_EQ(torn[0].strand, 7u);
  EXPECT_NEAR(torn[0].stretch, 3.01, 1e-9);
  EXPECT_EQ(set.cut[7], kStrandTorn);
  // It let go whole, once.
  EXPECT_EQ(w.state.constraints.distance.size(), constraints_before - set.segments);
  EXPECT_EQ(tear_overstretched_strands(w, torn), 0u);
  // The cautery does not divide it again.
  surgery::CutPlane everywhere{};
  everywhere.p = w.state.particles.position[set.particle(7, 1)];
  everywhere.n = Vec3::UnitX(), everywhere.l = Vec3::UnitY(), everywhere.f = Vec3::UnitZ();
  std::vector<surgery::StrandCut> cuts;
  surgery::cut_strands(w, everywhere, Real(1), cuts);
  for (const surgery::StrandCut& c : cuts)
    EXPECT_FALSE(c.set == patch.fascia_fat && c.strand == 7u);
  EXPECT_EQ(set.cut[7], kStrandTorn);
}

TEST(StrandTear, TornStrandsDissolveLikeDividedOnes) {
  ThoracicPatch patch = make_thoracic_patch(default_thoracic_patch_params());
  TissueWorld& w = patch.world;
  StrandSet& set = w.strands[patch.ima_fat];
  stretch_strand(w, set, 3, Real(4));
  std::vector<StrandTear> torn;
  ASSERT_EQ(tear_overstretched_strands(w, torn), 1u);
  const surgery::StrandCutParams params;
  const std::uint32_t n = surgery::steps_to_vanish(params, set.diameter[3 * (set.segments + 1)]);
  std::uint32_t removed = 0;
  for (std::uint32_t step = 0; step < n; ++step)
    removed += surgery::dissolve_cut_strands(w, params);
  EXPECT_EQ(removed, set.segments + 1);
  for (std::uint32_t k = 0; k <= set.segments; ++k)
    EXPECT_EQ(w.state.particles.inverse_mass[set.particle(3, k)], 0);
}

TEST(StrandTear, RejectsATearStretchOfOneOrLess) {
  ThoracicPatchParams p = default_thoracic_patch_params();
  p.fascia_fat.tear_stretch = 1;
  EXPECT_THROW(make_thoracic_patch(p), std::invalid_argument);
}

// A piece of tissue carried away with strand ends on it: the wall under one strand's end moved
// 1 mm a step for 25 cm (in a session, a piece of fascia the cuts freed falling away). Returns
// the strands torn, in order; each tears at the first step its ends are past tear_stretch.
std::vector<StrandTear> carry_a_wall_face_away(Real tear_stretch, std::uint32_t& fascia_fat) {
  ThoracicPatchParams p = default_thoracic_patch_params();
  p.fascia_fat.tear_stretch = p.ima_fat.tear_stretch = tear_stretch;
  ThoracicPatch patch = make_thoracic_patch(p);
  fascia_fat = patch.fascia_fat;
  TissueWorld& w = patch.world;
  const StrandSet& set = w.strands[patch.fascia_fat];
  const MeshObject& wall = w.meshes[patch.wall];
  const geometry::Triangle& face = wall.triangles[set.end_b[0].triangle];
  const physics::Particles& P = w.state.particles;
  physics::Executor exec(1);
  std::vector<StrandTear> torn;
  for (int step = 0; step < 300; ++step) {
    // The wall is static: its vertices go where they are put.
    if (step < 250)
      for (std::uint32_t v : face)
        w.state.particles.position[wall.first_particle + v] -= Vec3(0, 0.001, 0);
    EXPECT_TRUE(step_tissue(w, exec).ok()) << step;
    const std::size_t before = torn.size();
    tear_overstretched_strands(w, torn);
    surgery::dissolve_cut_strands(w, surgery::StrandCutParams{});
    for (std::size_t k = before; k < torn.size(); ++k) {
      // Torn at this step: the previous step's 1 mm less was within the limit.
      const StrandSet& s = w.strands[torn[k].set];
      const std::uint32_t a = s.particle(torn[k].strand, 0);
      const std::uint32_t b = s.particle(torn[k].strand, s.segments);
      const Real rest = (P.rest_position[b] - P.rest_position[a]).norm();
      EXPECT_GT(torn[k].stretch, tear_stretch);
      EXPECT_LT(torn[k].stretch, tear_stretch + Real(0.0011) / rest + Real(1e-9));
    }
  }
  return torn;
}

TEST(StrandTear, StrandsOnTissueCarriedAwayTearAsTheyPassTheLimit) {
  std::uint32_t fascia_fat = 0;
  const std::vector<StrandTear> torn = carry_a_wall_face_away(3, fascia_fat);
  // At least the strand that ends on the face, and only strands of the face's neighbourhood.
  bool first = false;
  for (const StrandTear& t : torn)
    first = first || (t.set == fascia_fat && t.strand == 0u);
  EXPECT_TRUE(first);
  EXPECT_LT(torn.size(), 40u);
  // Allowed to stretch 300 times, none tears over 25 cm.
  EXPECT_TRUE(carry_a_wall_face_away(300, fascia_fat).empty());
}

}  // namespace
}  // namespace imasim::tissue
