#include "surgery/strand_cut.hpp"

#include <algorithm>
#include <cmath>

namespace imasim::surgery {

CutPlane cut_plane(const Pose& tool) {
  return {tool.translation, tool.rotate(Vec3::UnitY()), tool.rotate(Vec3::UnitX()),
          tool.rotate(Vec3::UnitZ())};
}

namespace {

// Does the segment a-b (in the plane's (l, f) coordinates) meet the open square |u|, |v| < h?
// Liang-Barsky clipping against the four slabs.
bool segment_meets_square(Real au, Real av, Real bu, Real bv, Real h) {
  Real t0 = 0, t1 = 1;
  const Real d[2] = {bu - au, bv - av}, a[2] = {au, av};
  for (int k = 0; k < 2; ++k) {
    if (d[k] == 0) {
      if (!(std::abs(a[k]) < h)) return false;
      continue;
    }
    Real ta = (-h - a[k]) / d[k], tb = (h - a[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta), t1 = std::min(t1, tb);
  }
  return t0 < t1 || (t0 == t1 && t0 > 0 && t0 < 1);
}

}  // namespace

bool segment_is_cut(const CutPlane& c, Real omega, const Vec3& v0, const Vec3& v1) {
  const Real h = omega / 2;
  const Real s0 = c.n.dot(v0 - c.p), s1 = c.n.dot(v1 - c.p);
  if ((s0 > 0 && s1 > 0) || (s0 < 0 && s1 < 0)) return false;  // both on one side
  if (s0 == s1) {  // both zero: the segment lies in the plane
    return segment_meets_square(c.l.dot(v0 - c.p), c.f.dot(v0 - c.p), c.l.dot(v1 - c.p),
                                c.f.dot(v1 - c.p), h);
  }
  const Real t = s0 / (s0 - s1);  // n.(x - p) = 0 at x = v0 + t (v1 - v0), t in [0, 1]
  const Vec3 x = v0 + t * (v1 - v0);
  return std::abs(c.l.dot(x - c.p)) < h && std::abs(c.f.dot(x - c.p)) < h;
}

std::uint32_t cut_strands(tissue::TissueWorld& w, const CutPlane& plane, Real omega,
                          std::vector<StrandCut>& cuts) {
  const std::vector<Vec3>& x = w.state.particles.position;
  std::uint32_t count = 0;
  for (std::uint32_t s = 0; s < w.strands.size(); ++s) {
    tissue::StrandSet& set = w.strands[s];
    for (std::uint32_t i = 0; i < set.strand_count; ++i) {
      if (set.cut[i]) continue;
      for (std::uint32_t k = 0; k < set.segments; ++k) {
        if (!segment_is_cut(plane, omega, x[set.particle(i, k)], x[set.particle(i, k + 1)]))
          continue;
        // The whole strand lets go, not only the cut segment: it dissolves over the next steps
        // (eq. 13) anyway, and the halves of a strand stretched by tissue that fell away (tens
        // of millimetres a segment) would recoil at metres a second and stop the step at the
        // speed guard.
        for (std::uint32_t j = 0; j < set.segments; ++j)
          w.state.constraints.distance.remove(set.segment_constraint[i * set.segments + j]);
        set.cut[i] = tissue::kStrandDivided;
        cuts.push_back({s, i, k});
        ++count;
        break;
      }
    }
  }
  return count;
}

namespace {

// Drops the coupling pairs that read or write a particle of `removed` (sorted): one pass over
// each coupling however many particles went.
void uncouple(tissue::TissueWorld& w, const std::vector<std::uint32_t>& removed) {
  auto gone = [&](std::uint32_t p) {
    return std::binary_search(removed.begin(), removed.end(), p);
  };
  for (tissue::OffsetCoupling& c : w.couplings)
    std::erase_if(c.pairs, [&](const auto& pair) { return gone(pair.first) || gone(pair.second); });
}

}  // namespace

std::uint32_t dissolve_cut_strands(tissue::TissueWorld& w, const StrandCutParams& params) {
  physics::Particles& P = w.state.particles;
  std::vector<std::uint32_t> removed;  // allocates only when particles go
  for (tissue::StrandSet& set : w.strands) {
    for (std::uint32_t i = 0; i < set.strand_count; ++i) {
      if (!set.cut[i]) continue;
      for (std::uint32_t k = 0; k <= set.segments; ++k) {
        const std::uint32_t local = i * (set.segments + 1) + k;
        Real& d = set.diameter[local];
        if (d == 0) continue;
        d *= params.shrink;  // eq. 13
        if (d >= params.vanish_diameter) continue;
        d = 0;
        const std::uint32_t p = set.particle(i, k);
        // Its segments' constraints (the cut one is already gone: remove() ignores stale ones).
        if (k > 0)
          w.state.constraints.distance.remove(set.segment_constraint[i * set.segments + k - 1]);
        if (k < set.segments)
          w.state.constraints.distance.remove(set.segment_constraint[i * set.segments + k]);
        P.inverse_mass[p] = 0;
        P.velocity[p] = Vec3::Zero();
        removed.push_back(p);
      }
    }
  }
  if (!removed.empty()) {
    std::sort(removed.begin(), removed.end());
    uncouple(w, removed);
  }
  return static_cast<std::uint32_t>(removed.size());
}

std::uint32_t steps_to_vanish(const StrandCutParams& params, Real d0) {
  std::uint32_t n = 0;
  for (Real d = d0; d >= params.vanish_diameter; d *= params.shrink)
    ++n;
  return n;
}

}  // namespace imasim::surgery
