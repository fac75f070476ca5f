#pragma once
// Damping (eq. 4), SPEC S1 reading: k_l and k_c are dimensionless shares removed per 5 ms
// (kDampingReferenceStep), applied over a substep of length h as the equivalent rate:
//   keep(k, h) = (1 - k)^(h / 5 ms),
// so n substeps of dt / n remove exactly the share k per 5 ms whatever n, the particles' masses
// and the mesh resolution.
#include "physics/executor.hpp"
#include "physics/model.hpp"
#include "physics/state.hpp"

namespace imasim::physics {

// The factor a velocity keeps over a time h under damping k (unit of h: s).
Real damping_keep(Real k, Real h);

// Linear (k_l): v <- keep(k_l, h) v for every dynamic particle, folded into the step's velocity
// update (step.cpp).

// Angular (k_c), Mueller et al. 2007 ("Position based dynamics", 3.5): per object, the rigid
// motion of its dynamic particles, v_cm + omega x r_i with omega = I^-1 L about the centre of
// mass, is kept and each particle's deviation from it is reduced:
//   v_i <- v_i + (1 - keep(k_c, h)) (v_cm + omega x r_i - v_i).
// Rigid translation and rotation pass untouched; internal (deforming) motion is damped. An
// object whose inertia is singular (a line or a point) is not damped: its rotation about itself
// is undefined. Serial in particle order over the object's dynamic particles (their range as the
// step found it), so the sums are thread-independent.
void apply_angular_damping(const Model& model, State& state, std::size_t object, Real h);

}  // namespace imasim::physics
