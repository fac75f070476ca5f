#include "tissue/implicit_rows.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace imasim::tissue {

namespace {

// A row's stiffness, 1 / (alpha s) (unit: N/m for a distance, N m for a dihedral).
Real row_stiffness(const physics::Model& model, physics::MaterialId material, Real scale,
                   const std::string& row) {
  const physics::ConstraintMaterial& m = model.materials.at(material);
  const Real compliance = m.compliance * scale;
  if (m.response != physics::Response::xpbd || !(compliance > 0))
    throw std::invalid_argument(row + ": an implicit step needs a compliant XPBD row");
  return 1 / compliance;
}

const MeshObject& mesh_of(const TissueWorld& world, std::uint32_t mesh) {
  if (mesh >= world.meshes.size())
    throw std::invalid_argument("implicit rows: mesh " + std::to_string(mesh) + " of " +
                                std::to_string(world.meshes.size()));
  return world.meshes[mesh];
}

}  // namespace

MeshRows rows_of_mesh(const TissueWorld& world, std::uint32_t mesh) {
  const MeshObject& object = mesh_of(world, mesh);
  const std::uint32_t first = object.first_particle, end = first + object.particle_count;
  const std::string name = "implicit rows of '" + object.name + "'";
  // Mesh-local index of a particle of the mesh; throws for one outside it.
  auto local = [&](std::uint32_t p) {
    if (p < first || p >= end)
      throw std::invalid_argument(name + ": a row joins particle " + std::to_string(p) +
                                  " of another object");
    return p - first;
  };
  auto of_mesh = [&](std::uint32_t p) { return p >= first && p < end; };
  const physics::Model& model = world.model;
  const physics::ConstraintSystem& cs = world.state.constraints;
  MeshRows rows;
  rows.mesh = mesh;
  for (const auto& group : cs.distance.groups()) {
    for (const physics::DistanceRow& r : group.rows) {
      if (!of_mesh(r.i) && !of_mesh(r.j)) continue;
      physics::StiffeningSpring s;
      s.rest_length = r.rest_length;
      s.toe_stiffness = s.linear_stiffness =
          row_stiffness(model, r.material, r.compliance_scale, name + ": distance row");
      s.toe_strain = Real(1);  // one law throughout: the row's
      rows.edges.push_back({local(r.i), local(r.j), s});
    }
  }
  for (const auto& group : cs.dihedral.groups()) {
    for (const physics::DihedralRow& r : group.rows) {
      if (std::none_of(r.p.begin(), r.p.end(), of_mesh)) continue;
      physics::MembraneDihedral d;
      for (std::uint32_t q = 0; q < 4; ++q)
        d.v[q] = local(r.p[q]);
      d.rest_angle = r.rest_angle();
      d.stiffness = row_stiffness(model, r.material, r.compliance_scale, name + ": dihedral row");
      rows.dihedrals.push_back(d);
    }
  }
  return rows;
}

physics::ImplicitMembrane implicit_membrane_of_rows(const TissueWorld& world, const MeshRows& rows,
                                                    Real h, std::uint32_t bodies) {
  const MeshObject& object = mesh_of(world, rows.mesh);
  const physics::Particles& particles = world.state.particles;
  std::vector<Real> mass(object.particle_count, Real(0));
  std::vector<std::uint8_t> fixed(object.particle_count, 0);
  for (std::uint32_t k = 0; k < object.particle_count; ++k) {
    const Real w = particles.inverse_mass[object.first_particle + k];
    fixed[k] = w == 0;
    mass[k] = w > 0 ? 1 / w : Real(0);
  }
  return physics::ImplicitMembrane(std::move(mass), fixed, rows.edges, h, {}, bodies,
                                   rows.dihedrals);
}

physics::ImplicitMembrane implicit_membrane_of_rows(const TissueWorld& world, std::uint32_t mesh,
                                                    Real h, std::uint32_t bodies) {
  return implicit_membrane_of_rows(world, rows_of_mesh(world, mesh), h, bodies);
}

}  // namespace imasim::tissue
