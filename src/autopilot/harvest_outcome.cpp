#include "autopilot/harvest_outcome.hpp"

#include <limits>

#include "geometry/closest_point.hpp"

namespace imasim::autopilot {

namespace {

// A strand belongs to the segment when its vessel end lies within this of the segment's
// centerline (the vessel's radius and more), not past its ends.
constexpr Real kPedicleReach = Real(0.004);  // (unit: m)

bool beside_segment(const Vec3& p, const std::vector<Vec3>& segment) {
  for (std::size_t i = 1; i < segment.size(); ++i) {
    const Vec3 &a = segment[i - 1], &b = segment[i];
    const Real u = geometry::closest_segment_parameter(p, a, b);
    if ((i == 1 && u <= 0) || (i + 1 == segment.size() && u >= 1)) continue;  // past an end
    if ((p - ((1 - u) * a + u * b)).norm() < kPedicleReach) return true;
  }
  return false;
}

}  // namespace

HarvestOutcome harvest_outcome(const session::SurgicalSession& s, const HarvestPlan& plan) {
  HarvestOutcome out;
  const tissue::TissueWorld& w = s.scene.patch.world;
  const tissue::StrandSet& set = w.strands[s.scene.patch.ima_fat];
  const bool vessel_first = set.mesh_a == s.scene.patch.ima;
  for (std::uint32_t k = 0; k < set.strand_count; ++k) {
    const std::uint32_t end = vessel_first ? set.particle(k, 0) : set.particle(k, set.segments);
    if (!beside_segment(w.state.particles.rest_position[end], plan.segment)) continue;
    ++out.pedicle_strands;
    if (set.cut[k] == tissue::kStrandDivided) ++out.pedicle_strands_divided;  // not torn
  }
  out.fascia_edges_cut = s.fascia_edges_cut;
  for (const surgery::Event& e : s.events.events)
    if (e.kind == surgery::EventKind::injury) ++out.ima_injuries;
  return out;
}

bool harvest_finished(const HarvestOutcome& o) {
  return o.pedicle_strands > 0 && o.divided_share() >= kPedicleFreeShare &&
         o.fascia_edges_cut > 0 && o.ima_injuries == 0;
}

}  // namespace imasim::autopilot
