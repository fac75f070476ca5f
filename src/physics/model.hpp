#pragma once
// The immutable description of a simulation: solver settings, per-object parameters and
// constraint materials. Built once, then only read (step takes it by const reference).
#include <cstdint>
#include <string>
#include <vector>

#include "math/types.hpp"
#include "physics/material.hpp"

namespace imasim::physics {

struct SolverParams {
  Real dt = Real(0.005);         // step (unit: s); the paper's 5 ms (2.3.1)
  std::uint32_t substeps = 1;    // n substeps per step, each of length dt / n
  std::uint32_t iterations = 5;  // k projection sweeps per substep; the paper's 5 (2.3.1)
  Real max_speed = 50;  // divergence guard (unit: m/s): a particle faster over the step fails it
  // How fast a contact pushes out a particle that was already inside its surface when the step
  // began (unit: m/s): the tool put down inside the fat, a device pose that jumps. Resolved in
  // one substep, such an overlap D would launch the particle's neighbours at D / h, a speed that
  // grows as the substeps shrink (docs/physics.md); at this speed it is h-independent.
  // Penetration that arises within the step is corrected at once. 0.5 m/s clears 2.5 mm a step
  // (an instrument's jaws are a few mm thick) and stays below what the fascia amplifies at 512
  // substeps (measured: bounded up to 1 m/s, diverging at 5).
  Real push_out_speed = Real(0.5);
  // Coarse objects (ObjectParams::coarse) are stepped every coarse_stride-th substep with a
  // substep coarse_stride times longer: soft bodies that converge with fewer substeps (the fat
  // strands) cost less. 1 = every object at every substep; a stride that does not divide
  // substeps is reduced to their greatest common divisor (effective_coarse_stride).
  std::uint32_t coarse_stride = 1;
  // Bending (dihedral) rows of the fine objects are projected every bending_stride-th substep,
  // each projection carrying the impulse of bending_stride substeps (alpha_tilde = alpha /
  // (stride h^2)). Bending is soft next to stretching, so its rows need fewer projections to
  // converge (docs/physics.md). 1 = every substep; reduced like coarse_stride.
  std::uint32_t bending_stride = 1;
  // Sweeps per iteration of the fine objects' stiff rows (stretch, attachments) and of what they
  // act against (contacts, the proxies' coupling), lambdas accumulating; bending and the coarse
  // objects once. One sweep leaves a stretch row the effective compliance alpha + w h^2: a
  // membrane reads soft by about (c h / l)^2, c its wave speed and l its edge, which a further
  // sweep mostly takes away for the price of these rows alone (docs/physics.md). 1 = one sweep.
  std::uint32_t stretch_sweeps = 1;
  // Sweeps per iteration of the coarse band in each coarse substep, lambdas accumulating: the
  // first over all its rows (bending too), the further ones over the rows of the particles acted
  // on from outside (contacts, held particles, columns: active_rows.hpp), each with the band's
  // follow rows, contacts and held particles. The coarse substep is coarse_stride times longer,
  // so one sweep leaves the strands (c h_c / l)^2 soft where a tool pulls them: a strand pulled
  // by the grasp read 16 % soft at 8 coarse substeps of one sweep (docs/physics.md). 1 = one.
  std::uint32_t coarse_sweeps = 1;

  std::uint32_t effective_coarse_stride() const;
  std::uint32_t effective_bending_stride() const;
};

// Damping (eq. 4) as the paper's engine (iMSTK) reads k_l = 0.03 and k_c = 0.01 (SPEC S1): a
// dimensionless share of velocity removed per step of this length, the paper's 5 ms. Applied at
// the equivalent rate per substep, so it depends on neither mass, resolution nor substep count.
inline constexpr Real kDampingReferenceStep = Real(0.005);  // (unit: s)

// One simulated object (fascia, vessel, strands ...): its own gravity and damping (eq. 4).
struct ObjectParams {
  std::string name;
  Vec3 gravity = Vec3(0, Real(-9.81), 0);  // external acceleration a_ext of eq. 1 (unit: m/s^2)
  // k_l of eq. 4: share of every particle's velocity removed per 5 ms, in [0, 1).
  Real linear_damping = 0;
  // k_c of eq. 4 on a deformable body: share of each particle's deviation from the body's rigid
  // motion removed per 5 ms, in [0, 1] (Mueller et al. 2007, PBD damping): rigid translation and
  // rotation are never slowed.
  Real angular_damping = 0;
  // Stepped at the coarse rate (SolverParams::coarse_stride). Its constraints must join only its
  // own particles or other coarse ones (they are projected in its substeps only).
  bool coarse = false;
};

// A stride of substeps that divides the substep count: their greatest common divisor.
inline std::uint32_t stride_dividing(std::uint32_t stride, std::uint32_t substeps) {
  std::uint32_t a = stride < 1 ? 1 : stride, b = substeps < 1 ? 1 : substeps;
  while (b != 0) {
    const std::uint32_t r = a % b;
    a = b;
    b = r;
  }
  return a;
}

inline std::uint32_t SolverParams::effective_coarse_stride() const {
  return stride_dividing(coarse_stride, substeps);
}

inline std::uint32_t SolverParams::effective_bending_stride() const {
  return stride_dividing(bending_stride, substeps);
}

struct Model {
  SolverParams solver;
  std::vector<ObjectParams> objects;
  std::vector<ConstraintMaterial> materials;

  MaterialId add_material(const ConstraintMaterial& m) {
    materials.push_back(m);
    return static_cast<MaterialId>(materials.size() - 1);
  }
};

}  // namespace imasim::physics
