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
  // One pass gathers the body's mass, first and second moments about a point of the body (its
  // first dynamic particle, so that the moments stay small next to the coordinates): the centre
  // of mass, its velocity, the angular momentum and the inertia about the centre follow from
  // them (parallel-axis theorem) without a second pass.
  const Vec3 origin = x[first];
  Real mass = 0;
  Vec3 moment = Vec3::Zero(), momentum = Vec3::Zero(), moment_of_momentum = Vec3::Zero();
  Real sxx = 0, syy = 0, szz = 0, sxy = 0, sxz = 0, syz = 0;  // sum m r r^T
  for (std::uint32_t i = first; i < end; ++i) {
    if (owner[i] != object || w[i] == 0) continue;
    const Real m = 1 / w[i];
    const Vec3 r = x[i] - origin;
    const Vec3 mr = m * r;
    mass += m;
    moment += mr;
    momentum += m * v[i];
    moment_of_momentum += mr.cross(v[i]);
    sxx += mr.x() * r.x(), syy += mr.y() * r.y(), szz += mr.z() * r.z();
    sxy += mr.x() * r.y(), sxz += mr.x() * r.z(), syz += mr.y() * r.z();
  }
  if (!(mass > 0)) return;
  const Vec3 c = moment / mass, v_cm = momentum / mass;  // c relative to origin
  const Vec3 centre = origin + c;
  // About the centre: L = sum m r x v - M c x v_cm; sum m r r^T - M c c^T; I = tr(A) 1 - A.
  const Vec3 angular_momentum = moment_of_momentum - mass * c.cross(v_cm);
  Mat3 A;
  A << sxx, sxy, sxz, sxy, syy, syz, sxz, syz, szz;
  A -= mass * c * c.transpose();
  const Mat3 inertia = A.trace() * Mat3::Identity() - A;
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
