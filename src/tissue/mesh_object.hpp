#pragma once
// Adding a simulated triangle surface to the world: particles with uniform mass (eq. 5),
// distance constraints on edges (eq. 2) and dihedral constraints on interior edges (eq. 3).
#include <optional>
#include <string>

#include "math/pose.hpp"
#include "physics/membrane_material.hpp"
#include "tissue/tissue_world.hpp"

namespace imasim::tissue {

struct MeshObjectParams {
  std::string name;
  Real total_mass = Real(0.01);  // M_total of eq. 5 (unit: kg)
  bool gravity = true;
  Real linear_damping = 0;   // k_l of eq. 4: share of velocity removed per 5 ms
  Real angular_damping = 0;  // k_c of eq. 4: share of non-rigid velocity removed per 5 ms
  // Materials: a membrane in physical units (the tissues), its compliances scaled per edge by the
  // rest geometry so that the response does not depend on the mesh; or, when unset, `stretch`
  // and `bend` applied to every row as given (verification scenes and tests).
  std::optional<physics::MembraneMaterial> membrane;
  physics::ConstraintMaterial stretch = physics::ConstraintMaterial::xpbd(0);
  physics::ConstraintMaterial bend = physics::ConstraintMaterial::xpbd(1);
  bool is_static = false;  // every particle fixed, no constraints (the support structure)
  bool coarse = false;     // stepped at the solver's coarse rate (physics::ObjectParams::coarse)
  // Particles reserved for the vertices that cutting adds (tissue/topology_change.hpp); a mesh
  // with spares keeps an edge index so that its topology can change.
  std::uint32_t spare_vertices = 0;
};

// Returns the index of the new mesh object in world.meshes. Throws std::invalid_argument for a
// non-manifold mesh or bad parameters. Set-up only.
std::uint32_t add_mesh_object(TissueWorld& world, const geometry::TriangleMesh& mesh,
                              const MeshObjectParams& params);

// Adds an object (gravity per the flag; stepped at the coarse rate when `coarse`) and returns
// its id.
physics::ObjectId add_object(TissueWorld& world, const std::string& name, bool gravity,
                             Real linear_damping, Real angular_damping, bool coarse = false);

// Particles of a mesh object as a span of positions.
inline std::span<const Vec3> mesh_positions(const TissueWorld& w, const MeshObject& m) {
  return {w.state.particles.position.data() + m.first_particle, m.particle_count};
}

// Largest distance of a mesh object's vertices from their rest positions (unit: m).
double max_displacement(const TissueWorld& world, const MeshObject& mesh);

// Fascia superficialis (2.3.1): a w x h rectangle on an nx x ny grid, placed by `pose` (the
// rectangle's own frame has it in the x-z plane with normals along +y), perimeter fixed.
struct FasciaParams {
  Real width = Real(0.04), height = Real(0.15);  // (unit: m)
  std::uint32_t nx = 12, ny = 40;
  Pose pose;
  MeshObjectParams object;
};
FasciaParams default_fascia_params();
physics::MembraneMaterial default_fascia_membrane();
std::uint32_t add_fascia(TissueWorld& world, const FasciaParams& params);

}  // namespace imasim::tissue
