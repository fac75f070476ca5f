#pragma once
// Cutting the connective-tissue strands (paper 2.4.2, eq. 10-13; SPEC S4). The tool's pose
// gives the cutting plane through its position p with normal n (eq. 10) and the frame {n, l,
// f} = R (0, 1, 0), R (1, 0, 0), R (0, 0, 1). A strand segment (eq. 11) is cut when it crosses
// the plane inside the omega x omega square about p (eq. 12). A cut strand lets go at once (its
// segments no longer pull) and dissolves: its particles' diameters shrink d <- 0.96 d each step
// (eq. 13) and the particles are removed once d < 6e-4 m. A removed particle keeps its index
// (indices are handles elsewhere) but has no mass, no constraint, no coupling and no XSPH
// neighbour, and is not drawn (diameter 0).
#include <cstdint>
#include <vector>

#include "math/pose.hpp"
#include "tissue/tissue_world.hpp"

namespace imasim::surgery {

struct CutPlane {
  Vec3 p, n, l, f;  // eq. 10 and the tool frame
};
CutPlane cut_plane(const Pose& tool);

// eq. 12: some x on [v0, v1] has n.(x - p) = 0, |l.(x - p)| < omega/2 and |f.(x - p)| < omega/2.
// A segment lying in the plane is cut when it meets the open square.
bool segment_is_cut(const CutPlane& plane, Real omega, const Vec3& v0, const Vec3& v1);

struct StrandCutParams {
  Real width = Real(0.004);           // omega (unit: m)
  Real shrink = Real(0.96);           // eq. 13, per step
  Real vanish_diameter = Real(6e-4);  // (unit: m)
};

struct StrandCut {
  std::uint32_t set = 0, strand = 0, segment = 0;
};

// Cuts every intact strand with a segment that eq. 12 selects at the current positions: the
// strand's distance constraints (all its segments') are removed and the strand marked cut. Appends
// to `cuts`; returns how many strands were cut.
std::uint32_t cut_strands(tissue::TissueWorld& world, const CutPlane& plane, Real omega,
                          std::vector<StrandCut>& cuts);

// One step of eq. 13 for every cut strand's particles; removes those below the vanishing
// diameter (constraints, couplings, mass). Returns how many particles were removed.
std::uint32_t dissolve_cut_strands(tissue::TissueWorld& world, const StrandCutParams& params);

// Steps a particle of diameter d0 takes to vanish: the least n with d0 * shrink^n < vanish.
std::uint32_t steps_to_vanish(const StrandCutParams& params, Real d0);

}  // namespace imasim::surgery
