#pragma once
// The cloth verification scene (a contract other checks rely on): an N x N membrane of side L in
// the x-z plane at y = 0, perimeter fixed, total mass M spread evenly over all N^2 vertices,
// gravity (0, -9.81, 0), a distance constraint on every edge and a dihedral constraint on every
// interior edge. Vertex (i, j) is at (i L/(N-1), 0, j L/(N-1)) and is particle j N + i.
#include <cstdint>
#include <vector>

#include "geometry/triangle_mesh.hpp"
#include "physics/model.hpp"
#include "physics/state.hpp"

namespace imasim::scene {

struct ClothParams {
  std::uint32_t n = 32;          // vertices per side
  Real size = 1;                 // L (unit: m)
  Real mass = 1;                 // M (unit: kg)
  Real dt = Real(0.005);         // (unit: s)
  std::uint32_t iterations = 5;  // projection sweeps per substep
  std::uint32_t substeps = 1;
  Real max_speed = 50;      // divergence guard (unit: m/s)
  Real linear_damping = 0;  // eq. 4's k_l: share of velocity removed per 5 ms, in [0, 1)
  physics::Response response = physics::Response::pbd;
  Real pbd_distance_stiffness = 1;          // [0, 1]
  Real pbd_bending_stiffness = Real(0.01);  // [0, 1]
  Real distance_compliance = 0;             // (unit: m/N)
  Real bending_compliance = 0;              // (unit: rad/(N*m))
};

struct ClothScene {
  physics::Model model;
  physics::State state;
  geometry::TriangleMesh mesh;
  std::vector<std::uint32_t> centre_particles;  // 4 for even N, 1 for odd N
};

// Throws std::invalid_argument for parameters out of range (message names the parameter).
ClothScene make_cloth_scene(const ClothParams& params);

// Mean downward displacement of the centre particles (unit: m; positive = sagging).
Real centre_sag(const ClothScene& scene);
// Largest distance of any particle from its rest position (unit: m).
Real max_displacement(const physics::State& state);

}  // namespace imasim::scene
