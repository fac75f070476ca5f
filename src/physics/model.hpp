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
  Real max_speed = 50;           // divergence guard (unit: m/s): a faster particle fails the step
};

// One simulated object (fascia, vessel, strands ...): its own gravity and damping (eq. 4).
struct ObjectParams {
  std::string name;
  Vec3 gravity = Vec3(0, Real(-9.81), 0);  // external acceleration a_ext of eq. 1 (unit: m/s^2)
  Real linear_damping = 0;                 // k_l of eq. 4 (unit: kg/s)
  Real angular_damping = 0;                // k_c of eq. 4 (unit: kg*m^2/s)
};

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
