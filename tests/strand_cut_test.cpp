// Strand cutting (eq. 10-13): eq. 12 exact on synthetic segments; cut strands dissolve in
// ceil(ln(6e-4 / d0) / ln 0.96) steps and leave no constraint or coupling on removed particles.
#include "surgery/strand_cut.hpp"

#include <gtest/gtest.h>

#include "physics/executor.hpp"
#include "tissue/thoracic_patch.hpp"
#include "tissue/tissue_step.hpp"

namespace imasim::surgery {
namespace {

constexpr Real kOmega = 0.004;

TEST(StrandCut, FrameComesFromTheToolRotation) {
  Pose tool;
  tool.rotation = axis_angle(Vec3(1, -2, 0.5).normalized(), 1.1);
  tool.translation = Vec3(0.1, 0.2, 0.3);
  const CutPlane c = cut_plane(tool);
  EXPECT_EQ(c.p, tool.translation);
  EXPECT_EQ(c.n, tool.rotation.col(1));  // R (0, 1, 0)
  EXPECT_EQ(c.l, tool.rotation.col(0));  // R (1, 0, 0)
  EXPECT_EQ(c.f, tool.rotation.col(2));  // R (0, 0, 1)
}

TEST(StrandCut, Eq12OnSegmentsThroughTheAxisAlignedSquare) {
  const CutPlane c = cut_plane(Pose{});  // p = 0, n = y, l = x, f = z
  const Real h = kOmega / 2;
  auto crossing = [&](Real u, Real v) {
    return segment_is_cut(c, kOmega, Vec3(u, -0.01, v), Vec3(u, 0.02, v));
  };
  EXPECT_TRUE(crossing(0, 0));
  EXPECT_TRUE(crossing(0.0019, -0.0019));
  EXPECT_FALSE(crossing(0.0021, 0));
  EXPECT_FALSE(crossing(0, -0.0021));
  EXPECT_FALSE(crossing(h, 0));  // |l.(x - p)| < omega / 2 is strict
  EXPECT_FALSE(crossing(0, -h));
  EXPECT_TRUE(crossing(std::nextafter(h, Real(0)), 0));
  // Not reaching the plane; touching it at an end; lying in it.
  EXPECT_FALSE(segment_is_cut(c, kOmega, Vec3(0, 1e-9, 0), Vec3(0, 0.01, 0)));
  EXPECT_TRUE(segment_is_cut(c, kOmega, Vec3(0, 0, 0), Vec3(0, 0.01, 0)));
  EXPECT_TRUE(segment_is_cut(c, kOmega, Vec3(-1, 0, 0.001), Vec3(1, 0, 0.001)));
  EXPECT_FALSE(segment_is_cut(c, kOmega, Vec3(-1, 0, 0.003), Vec3(1, 0, 0.003)));
  EXPECT_FALSE(segment_is_cut(c, kOmega, Vec3(0.003, 0, -1), Vec3(0.004, 0, 1)));
  EXPECT_TRUE(segment_is_cut(c, kOmega, Vec3(-0.003, 0, 0.0035), Vec3(0.0035, 0, -0.003)));
}

TEST(StrandCut, Eq12OnObliqueSegmentsOfATurnedTool) {
  Pose tool;
  tool.rotation = axis_angle(Vec3(0.3, 1, -0.7).normalized(), 2.2);
  tool.translation = Vec3(-0.02, 0.01, 0.05);
  const CutPlane c = cut_plane(tool);
  // A segment crossing the plane at (l, f) = (a, b) from the centre, slanted along l and f.
  auto crosses_at = [&](Real a, Real b) {
    const Vec3 x = c.p + a * c.l + b * c.f;
    const Vec3 slant = 0.3 * c.l - 0.2 * c.f;
    return segment_is_cut(c, kOmega, x - 0.004 * (c.n + slant), x + 0.006 * (c.n + slant));
  };
  EXPECT_TRUE(crosses_at(0.0015, -0.0015));
  EXPECT_TRUE(crosses_at(-0.0019, 0.0019));
  EXPECT_FALSE(crosses_at(0.0015, -0.0021));
  EXPECT_FALSE(crosses_at(-0.0021, 0.001));
}

TEST(StrandCut, VanishingStepsMatchTheClosedForm) {
  const StrandCutParams params;
  for (Real d0 : {0.001, 0.0015, 0.002, 0.0031, 0.01}) {
    const double closed_form = std::ceil(std::log(6e-4 / d0) / std::log(0.96));
    EXPECT_EQ(steps_to_vanish(params, d0), static_cast<std::uint32_t>(closed_form)) << d0;
  }
}

// Every distance constraint's particles, for checking that none is a removed particle.
std::vector<std::uint32_t> constrained_particles(const tissue::TissueWorld& w) {
  std::vector<std::uint32_t> out;
  for (const auto& g : w.state.constraints.distance.groups())
    for (const physics::DistanceRow& r : g.rows)
      out.push_back(r.i), out.push_back(r.j);
  return out;
}

TEST(StrandCut, CutStrandsDissolveAndLeaveNothingBehind) {
  tissue::ThoracicPatch patch =
      tissue::make_thoracic_patch(tissue::default_thoracic_patch_params());
  tissue::TissueWorld& w = patch.world;
  const std::size_t constraints_before = w.state.constraints.distance.size();
  // A hook held across the fat beside the vessel: the plane's normal along x (lateral), the
  // square's sides along the wall's normal and the vessel.
  Pose tool;
  tool.rotation = axis_angle(Vec3::UnitZ(), -kPi / 2);  // n = R y = x
  tool.translation = Vec3(0.004, -0.004, 0.06);
  std::vector<StrandCut> cuts;
  const CutPlane plane = cut_plane(tool);
  const std::uint32_t cut = cut_strands(w, plane, 0.02, cuts);
  ASSERT_GT(cut, 0u);
  ASSERT_EQ(cuts.size(), cut);
  // The cut strands let go whole: every segment's constraint goes.
  std::size_t segments_cut = 0;
  for (const StrandCut& c : cuts)
    segments_cut += w.strands[c.set].segments;
  EXPECT_EQ(w.state.constraints.distance.size(), constraints_before - segments_cut);
  EXPECT_EQ(cut_strands(w, plane, 0.02, cuts), 0u);  // a strand is cut once

  const StrandCutParams params;
  const tissue::StrandSet& first_set = w.strands[cuts.front().set];
  const Real d0 = first_set.diameter[cuts.front().strand * (first_set.segments + 1) + 1];
  const std::uint32_t n = steps_to_vanish(params, d0);
  physics::Executor exec(1);
  std::uint32_t removed = 0;
  for (std::uint32_t step = 1; step <= n; ++step) {
    removed += dissolve_cut_strands(w, params);
    if (step < n) {
      EXPECT_EQ(removed, 0u) << "step " << step;
    }
    ASSERT_TRUE(tissue::step_tissue(w, exec).ok());
  }
  std::uint32_t expected = 0;
  for (const StrandCut& c : cuts)
    expected += w.strands[c.set].segments + 1;
  EXPECT_EQ(removed, expected);

  // Nothing refers to a removed particle; the removed ones are massless and still.
  std::vector<bool> gone(w.state.particles.size(), false);
  for (const StrandCut& c : cuts) {
    const tissue::StrandSet& set = w.strands[c.set];
    for (std::uint32_t k = 0; k <= set.segments; ++k) {
      gone[set.particle(c.strand, k)] = true;
      EXPECT_EQ(set.diameter[c.strand * (set.segments + 1) + k], 0);
      EXPECT_EQ(w.state.particles.inverse_mass[set.particle(c.strand, k)], 0);
    }
  }
  for (std::uint32_t p : constrained_particles(w))
    ASSERT_FALSE(gone[p]) << "constraint on removed particle " << p;
  for (const tissue::OffsetCoupling& c : w.couplings)
    for (const auto& [src, dst] : c.pairs)
      ASSERT_FALSE(gone[src] || gone[dst]) << c.name;
  for (int step = 0; step < 50; ++step)
    ASSERT_TRUE(tissue::step_tissue(w, exec).ok());
  for (const Vec3& x : w.state.particles.position)
    ASSERT_TRUE(x.allFinite());
}

}  // namespace
}  // namespace imasim::surgery
