#include "tissue/implicit_fascia.hpp"

#include <stdexcept>
#include <string>

namespace imasim::tissue {

ImplicitFascia make_implicit_fascia(const TissueWorld& world, std::uint32_t mesh,
                                    const physics::StiffeningMembrane& material,
                                    Real bending_stiffness, Real h, std::uint32_t bodies) {
  if (mesh >= world.meshes.size())
    throw std::invalid_argument("implicit fascia: mesh " + std::to_string(mesh) + " of " +
                                std::to_string(world.meshes.size()));
  const MeshObject& object = world.meshes[mesh];
  const physics::Particles& particles = world.state.particles;
  geometry::TriangleMesh rest;
  rest.triangles = object.triangles;
  std::vector<Real> mass(object.particle_count, Real(0));
  std::vector<std::uint8_t> fixed(object.particle_count, 0);
  for (std::uint32_t k = 0; k < object.particle_count; ++k) {
    const std::uint32_t p = object.first_particle + k;
    rest.vertices.push_back(particles.rest_position[p]);
    const Real w = particles.inverse_mass[p];
    fixed[k] = w == 0;
    mass[k] = w > 0 ? 1 / w : Real(0);
  }
  ImplicitFascia fascia;
  fascia.mesh = mesh;
  fascia.membrane.emplace(std::move(mass), fixed, physics::membrane_springs(rest, material), h,
                          physics::membrane_hinges(rest, bending_stiffness), bodies);
  fascia.x.resize(object.particle_count);
  fascia.v.resize(object.particle_count);
  return fascia;
}

physics::ImplicitStepReport step_implicit_fascia(
    ImplicitFascia& fascia, TissueWorld& world, const physics::Executor& exec, const Vec3& gravity,
    std::span<const physics::MembraneContact> contacts, std::span<physics::MembraneBody> bodies,
    const physics::ImplicitSolveParams& params,
    std::span<const physics::MembraneAttachment> attachments,
    std::span<const physics::MembraneBodyStop> body_stops,
    std::span<const physics::MembraneSupport> supports) {
  const MeshObject& object = world.meshes[fascia.mesh];
  physics::Particles& particles = world.state.particles;
  for (std::uint32_t k = 0; k < object.particle_count; ++k) {
    fascia.x[k] = particles.position[object.first_particle + k];
    fascia.v[k] = particles.velocity[object.first_particle + k];
  }
  const physics::ImplicitStepReport report = fascia.membrane->step(
      fascia.x, fascia.v, {gravity, {}, contacts, bodies, attachments, body_stops, supports},
      params, exec);
  for (std::uint32_t k = 0; k < object.particle_count; ++k) {
    const std::uint32_t p = object.first_particle + k;
    if (particles.inverse_mass[p] == 0) continue;
    particles.position[p] = fascia.x[k];
    particles.velocity[p] = fascia.v[k];
  }
  return report;
}

}  // namespace imasim::tissue
