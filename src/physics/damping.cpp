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
  // Raw pointers, so that the stores below do not make every particle reload the vectors'.
  const ObjectId* owner = P.object.data();
  const Real* w = P.inverse_mass.data();
  const Vec3* x = P.position.data();
  Vec3* v = P.velocity.data();
  // Centre of mass and momentum of the dynamic particles.
  Real mass = 0;
  Vec3 mass_position = Vec3::Zero(), momentum = Vec3::Zero();
  for (std::uint32_t i = first; i < end; ++i) {
    if (owner[i] != object || w[i] == 0) continue;
    const Real m = 1 / w[i];
    mass += m;
    mass_position += m * x[i];
    momentum += m * v[i];
  }
  if (!(mass > 0)) return;
  const Vec3 centre = mass_position / mass, v_cm = momentum / mass;
  // Angular momentum and inertia about the centre of mass.
  Vec3 angular_momentum = Vec3::Zero();
  Mat3 inertia = Mat3::Zero();
  for (std::uint32_t i = first; i < end; ++i) {
    if (owner[i] != object || w[i] == 0) continue;
    const Real m = 1 / w[i];
    const Vec3 r = x[i] - centre;
    angular_momentum += m * r.cross(v[i]);
    inertia += m * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
  }
  const Real scale = inertia.trace();
  if (!(std::abs(inertia.determinant()) > Real(1e-12) * scale * scale * scale)) return;
  const Vec3 omega = inertia.inverse() * angular_momentum;
  for (std::uint32_t i = first; i < end; ++i) {
    if (owner[i] != object || w[i] == 0) continue;
    const Vec3 rigid = v_cm + omega.cross(x[i] - centre);
    v[i] += rate * (rigid - v[i]);
  }
}

}  // namespace imasim::physics
