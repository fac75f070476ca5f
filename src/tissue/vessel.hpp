#pragma once
// The IMA vessel (2.3.2): a coarse tube simulated (stiff distance, soft dihedral, no gravity,
// uniform mass) and a fine visual tube that follows it through surface bindings.
#include "geometry/tube.hpp"
#include "tissue/mesh_object.hpp"

namespace imasim::tissue {

struct VesselParams {
  std::vector<Vec3> centerline;  // (unit: m)
  Real radius = Real(0.00125);   // the IMA is about 2-3 mm across
  // 80 rings (1.9 mm apart over the 15 cm segment): a hook pressing the vessel on its fat meets
  // within 4 % of what 160 rings give, 40 rings 12-17 % short (docs/physics.md).
  std::uint32_t coarse_segments = 6, coarse_rings = 80;
  std::uint32_t fine_segments = 12, fine_rings = 160;  // 4x the coarse vertices
  MeshObjectParams object;
};
VesselParams default_vessel_params();
physics::MembraneMaterial default_vessel_wall();

struct VesselIndices {
  std::uint32_t mesh = 0;    // coarse, simulated (world.meshes)
  std::uint32_t visual = 0;  // fine (world.visuals)
};

VesselIndices add_vessel(TissueWorld& world, const VesselParams& params);

// Binds a fine surface to a coarse mesh object: the mapping for any coarse-to-fine pair.
std::uint32_t add_visual_mesh(TissueWorld& world, std::uint32_t coarse_mesh,
                              const geometry::TriangleMesh& fine, Real search_radius);

}  // namespace imasim::tissue
