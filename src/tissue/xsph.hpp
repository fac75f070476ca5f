#pragma once
// XSPH-style velocity smoothing between neighbouring strand particles (SPEC S2 reading of the
// paper's "SPH-based interactions"): each interior particle's velocity moves towards its
// neighbours', each pair normalised symmetrically,
//   v_i' = v_i + c * sum_j W_ij (v_j - v_i) / max(S_i, S_j),   S_i = sum_j W_ij,
//   W_ij = (1 - r_ij / h)^2 for r < h,
// with r the current distance, h the neighbourhood radius and c in [0, 1]. What i gains from j,
// j loses to i (W and max(S_i, S_j) are symmetric, the neighbour lists are, and a set's particles
// have equal masses), so the set's momentum is conserved; normalising per particle (dividing by
// S_i alone) would not. Stable for any c in [0, 1]: c sum_j W_ij / max(S_i, S_j) <= c, so v_i' is
// a convex combination of v_i and its neighbours' (no velocity grows). It damps relative motion and
// leaves a common motion alone: the viscous feel of fat. Jacobi (all reads from the old
// velocities); allocation-free (scratch sized at set-up).
#include "physics/executor.hpp"
#include "tissue/tissue_world.hpp"

namespace imasim::tissue {

// In parallel over fixed chunks of pairs and of particles, each particle gathering its sums in
// one fixed order: the same bits on any thread count.
void smooth_strand_velocities(TissueWorld& world, const physics::Executor& exec);
// On the calling thread alone.
void smooth_strand_velocities(TissueWorld& world);

}  // namespace imasim::tissue
