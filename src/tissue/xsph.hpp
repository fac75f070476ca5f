#pragma once
// XSPH-style velocity smoothing between neighbouring strand particles (SPEC S2 reading of the
// paper's "SPH-based interactions"): each interior particle's velocity moves towards the
// kernel-weighted mean of its neighbours',
//   v_i' = v_i + c * sum_j W_ij (v_j - v_i) / sum_j W_ij,   W_ij = (1 - r_ij / h)^2 for r < h,
// with r the current distance, h the neighbourhood radius and c in [0, 1]. It damps relative
// motion and leaves a common motion alone: the viscous feel of fat. Jacobi (all reads from the
// old velocities), so the result does not depend on order.
#include "tissue/tissue_world.hpp"

namespace imasim::tissue {

void smooth_strand_velocities(TissueWorld& world);

}  // namespace imasim::tissue
