#include "tissue/thoracic_patch.hpp"

#include "tissue/tissue_step.hpp"

namespace imasim::tissue {

physics::SolverParams default_solver() {
  physics::SolverParams s;
  s.dt = Real(0.005);  // 2.3.1
  s.substeps = 32;
  s.iterations = 1;
  s.coarse_stride = 4;   // the fat strands: 8 substeps
  s.bending_stride = 2;  // the fascia's bending: 16 projections per step
  s.stretch_sweeps = 2;  // the fascia's stretch: within 5 % of a finer solve under a tool
  s.coarse_sweeps = 3;   // the strands pulled by the grasp: within 5 % of a finer solve
  return s;
}

ThoracicPatchParams default_thoracic_patch_params() {
  ThoracicPatchParams p;
  // Chest wall: radius 120 mm about an axis along z at y = -0.12 m, so the wall passes through
  // the origin; +-0.3 rad (+-36 mm) wide, 160 mm long; normals face the cavity (-y).
  p.wall.origin = Vec3(0, Real(-0.12), Real(-0.005));
  p.wall.axis = Vec3::UnitZ();
  p.wall.reference = Vec3::UnitY();
  p.wall.radius = Real(0.12);
  p.wall.angle0 = Real(-0.3);
  p.wall.angle1 = Real(0.3);
  p.wall.length = Real(0.16);
  p.wall.nu = 10;
  p.wall.nv = 24;

  p.vessel = default_vessel_params();
  p.vessel.centerline = {Vec3(0, Real(-0.004), 0), Vec3(0, Real(-0.004), Real(0.15))};

  p.fascia = default_fascia_params();
  p.fascia.pose.translation = Vec3(Real(-0.02), Real(-0.010), 0);  // 10 mm inside the wall

  p.ima_fat.name = "ima_fat";
  p.ima_fat.generation.strands_per_face = 1;
  p.ima_fat.generation.segments = 3;
  // eq. 6 would give the centre distance (2.5 mm), shorter than the 2.75 mm gap between the
  // vessel's surface and the wall: the patch gives d_max instead.
  p.ima_fat.generation.max_length = Real(0.006);
  p.ima_fat.generation.seed = 11;
  // The layer of fat holds the vessel both ways and pushes back when it is pressed: without its
  // columns the vessel gives a hook a tenth of its k_d (docs/haptics.md).
  p.ima_fat.resists_compression = true;
  p.ima_fat.total_mass = Real(0.002);

  p.fascia_fat.name = "fascia_fat";
  p.fascia_fat.generation.strands_per_face = 1;
  p.fascia_fat.generation.segments = 4;
  p.fascia_fat.generation.max_length = Real(0.015);
  p.fascia_fat.generation.seed = 12;
  p.fascia_fat.total_mass = Real(0.03);  // ~40 x 150 x 8 mm of fat at ~900 kg/m^3, in part
  return p;
}

ThoracicPatch make_thoracic_patch(const ThoracicPatchParams& p) {
  ThoracicPatch patch;
  TissueWorld& w = patch.world;
  w.model.solver = p.solver;
  MeshObjectParams wall;
  wall.name = "chest_wall";
  wall.is_static = true;
  wall.gravity = false;
  patch.wall = add_mesh_object(w, geometry::make_cylinder_patch(p.wall), wall);
  const VesselIndices vessel = add_vessel(w, p.vessel);
  patch.ima = vessel.mesh;
  patch.ima_visual = vessel.visual;
  patch.fascia = add_fascia(w, p.fascia);
  patch.ima_fat = add_strands(w, patch.ima, patch.wall, p.ima_fat);
  patch.fascia_fat = add_strands(w, patch.fascia, patch.wall, p.fascia_fat);

  // Coupling maps (2.3.3), built once from rest positions.
  const MeshObject& ima = w.meshes[patch.ima];
  const MeshObject& fascia = w.meshes[patch.fascia];
  std::vector<std::uint32_t> ima_particles, fascia_particles;
  for (std::uint32_t k = 0; k < ima.particle_count; ++k)
    ima_particles.push_back(ima.first_particle + k);
  for (std::uint32_t k = 0; k < fascia.particle_count; ++k) {
    fascia_particles.push_back(fascia.first_particle + k);
  }
  // The fat against the vessel: each strand's interior particle next to its end there.
  std::vector<std::uint32_t> fat_at_ima;
  const StrandSet& ima_strands = w.strands[patch.ima_fat];
  for (std::uint32_t s = 0; s < ima_strands.strand_count; ++s)
    fat_at_ima.push_back(ima_strands.particle(s, 1));
  const auto fascia_fat = interior_particles(w.strands[patch.fascia_fat]);
  const physics::Particles& P = w.state.particles;
  const Real r = p.coupling_radius, lmax = p.coupling_lambda_max;
  // Eq. 8: the vessel drives the fat against it unless that fat is manipulated, and the fascia
  // the fat under it. Eq. 9: the fat drives the vessel while it is manipulated (beta = 1), and
  // the vessel relaxes otherwise (beta = 0). A strand by the vessel is either driven by it or,
  // held, drives it: the couplings form no loop.
  w.couplings = {
      {"fat->ima", nearest_source_pairs(P, fat_at_ima, ima_particles, 2 * r), lmax,
       Beta::manipulated, Real(0.8), false},
      {"ima->fat", nearest_source_pairs(P, ima_particles, fat_at_ima, r), lmax, Beta::one,
       Real(0.8), true},
      {"fascia->fat", nearest_source_pairs(P, fascia_particles, fascia_fat, r), lmax, Beta::one,
       Real(0.8), false},
  };
  finish_setup(w);
  return patch;
}

}  // namespace imasim::tissue
