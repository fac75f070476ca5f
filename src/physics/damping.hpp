#pragma once
// Damping (eq. 4): F_d = -k_l v per particle and T_d = -k_c omega per object, both integrated
// implicitly over the substep h so that any k is stable.
#include "physics/executor.hpp"
#include "physics/model.hpp"
#include "physics/state.hpp"

namespace imasim::physics {

// Linear: m dv/dt = -k_l v  =>  v' = v / (1 + k_l w h), w = 1/m.
void apply_linear_damping(const Model& model, State& state, Real h, const Executor& exec);

// Angular (SPEC S1 reading, after Mueller et al.'s PBD damping): the rigid rotation omega of an
// object's velocity field about its centre of mass is slowed by the torque -k_c omega:
//   (I + k_c h E) omega' = L,  v_i += (omega' - omega) x r_i
// with I the inertia tensor and L the angular momentum about the centre of mass. Fixed
// particles are left out. Serial, in particle order, so the sums are thread-independent.
void apply_angular_damping(const Model& model, State& state, Real h);

}  // namespace imasim::physics
