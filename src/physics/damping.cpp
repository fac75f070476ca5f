#include "physics/damping.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace imasim::physics {

Real damping_keep(Real k, Real h) {
  if (!(k > 0)) return Real(1);
  return std::pow(Real(1) - std::min(k, Real(1)), h / kDampingReferenceStep);
}

void apply_angular_damping(const Model& model, State& state, std::size_t o, Real h) {
  const Real rate = 1 - damping_keep(model.objects[o].angular_damping, h);
  if (rate <= 0) return;
  Particles& P = state.particles;
  const ObjectRange& range = state.scratch.object_ranges[o];
  const auto object = static_cast<ObjectId>(o);
  const std::uint32_t first = range.dynamic_first, end = range.dynamic_end;
  // Centre of mass and momentum of the dynamic particles.
  Real mass = 0;
  Vec3 mass_position = Vec3::Zero(), momentum = Vec3::Zero();
  for (std::uint32_t i = first; i < end; ++i) {
    if (P.object[i] != object || P.inverse_mass[i] == 0) continue;
    const Real m = 1 / P.inverse_mass[i];
    mass += m;
    mass_position += m * P.position[i];
    momentum += m * P.velocity[i];
  }
  if (!(mass > 0)) return;
  const Vec3 centre = mass_position / mass, v_cm = momentum / mass;
  // Angular momentum and inertia about the centre of mass.
  Vec3 angular_momentum = Vec3::Zero();
  Mat3 inertia = Mat3::Zero();
  for (std::uint32_t i = first; i < end; ++i) {
    if (P.object[i] != object || P.inverse_mass[i] == 0) continue;
    const Real m = 1 / P.inverse_mass[i];
    const Vec3 r = P.position[i] - centre;
    angular_momentum += m * r.cross(P.velocity[i]);
    inertia += m * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
  }
  const Real scale = inertia.trace();
  if (!(std::abs(inertia.determinant()) > Real(1e-12) * scale * scale * scale)) return;
  const Vec3 omega = inertia.inverse() * angular_momentum;
  for (std::uint32_t i = first; i < end; ++i) {
    if (P.object[i] != object || P.inverse_mass[i] == 0) continue;
    const Vec3 rigid = v_cm + omega.cross(P.position[i] - centre);
    P.velocity[i] += rate * (rigid - P.velocity[i]);
  }
}

}  // namespace imasim::physics
