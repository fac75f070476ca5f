#include "tissue/vessel.hpp"

namespace imasim::tissue {

physics::MembraneMaterial default_vessel_wall() {
  physics::MembraneMaterial m;
  // The IMA's wall as a shell (docs/tissue.md): E about 1.5 MPa in the physiological range of
  // muscular arteries, wall 0.35 mm; bending from plate theory, so the paper's "stiff distance,
  // soft dihedral" (2.3.2) follows from the wall's thinness.
  m.youngs_modulus = Real(1.5e6);
  m.thickness = Real(0.35e-3);
  return m;
}

VesselParams default_vessel_params() {
  VesselParams v;
  v.object.name = "ima";
  v.object.total_mass = Real(0.001);  // 150 mm of a 2.5 mm vessel with its blood
  v.object.gravity = false;           // 2.3.2: gravity-free, in-situ
  v.object.membrane = default_vessel_wall();
  // Unloaded at rest, and as tube stiff under load at any affordable rate (docs/physics.md):
  // the coarse rate keeps its cost down.
  v.object.coarse = true;
  return v;
}

std::uint32_t add_visual_mesh(TissueWorld& world, std::uint32_t coarse_mesh,
                              const geometry::TriangleMesh& fine, Real search_radius) {
  const MeshObject& m = world.meshes[coarse_mesh];
  geometry::TriangleMesh coarse;
  const auto positions = mesh_positions(world, m);
  coarse.vertices.assign(positions.begin(), positions.end());
  coarse.triangles = m.triangles;
  VisualMesh v;
  v.source_mesh = coarse_mesh;
  v.triangles = fine.triangles;
  v.bindings = geometry::bind_to_surface(fine.vertices, coarse, search_radius);
  v.positions = fine.vertices;
  world.visuals.push_back(std::move(v));
  return static_cast<std::uint32_t>(world.visuals.size() - 1);
}

VesselIndices add_vessel(TissueWorld& world, const VesselParams& p) {
  geometry::TubeSpec coarse{p.centerline, p.radius, p.coarse_segments, p.coarse_rings};
  geometry::TubeSpec fine{p.centerline, p.radius, p.fine_segments, p.fine_rings};
  VesselIndices out;
  out.mesh = add_mesh_object(world, geometry::make_tube(coarse), p.object);
  out.visual = add_visual_mesh(world, out.mesh, geometry::make_tube(fine), 4 * p.radius);
  return out;
}

}  // namespace imasim::tissue
