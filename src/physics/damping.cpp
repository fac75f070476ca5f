#include "physics/damping.hpp"

#include <Eigen/LU>
#include <algorithm>

namespace imasim::physics {

void apply_linear_damping(const Model& model, State& state, Real h, const Executor& exec) {
  bool any = false;
  for (const ObjectParams& o : model.objects)
    any = any || o.linear_damping > 0;
  if (!any) return;
  Particles& P = state.particles;
  exec.for_chunks(P.size(), kParticleBlock, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      const Real kl = model.objects[P.object[i]].linear_damping;
      P.velocity[i] /= Real(1) + kl * P.inverse_mass[i] * h;
    }
  });
}

void apply_angular_damping(const Model& model, State& state, Real h) {
  bool any = false;
  for (const ObjectParams& o : model.objects)
    any = any || o.angular_damping > 0;
  if (!any) return;
  Particles& P = state.particles;
  auto& moments = state.scratch.object_moments;
  std::fill(moments.begin(), moments.begin() + static_cast<std::ptrdiff_t>(model.objects.size()),
            ObjectMoments{});
  const std::size_t n = P.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (P.inverse_mass[i] == 0) continue;
    ObjectMoments& m = moments[P.object[i]];
    const Real mass = Real(1) / P.inverse_mass[i];
    m.mass += mass;
    m.mass_position += mass * P.position[i];
    m.momentum += mass * P.velocity[i];
  }
  // Second pass about the centre of mass, for accuracy with objects far from the origin.
  for (std::size_t i = 0; i < n; ++i) {
    if (P.inverse_mass[i] == 0) continue;
    ObjectMoments& m = moments[P.object[i]];
    if (model.objects[P.object[i]].angular_damping <= 0) continue;
    const Real mass = Real(1) / P.inverse_mass[i];
    const Vec3 r = P.position[i] - m.mass_position / m.mass;
    m.angular_momentum += mass * r.cross(P.velocity[i]);
    m.inertia += mass * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
  }
  for (std::size_t o = 0; o < model.objects.size(); ++o) {
    ObjectMoments& m = moments[o];
    const Real kc = model.objects[o].angular_damping;
    if (kc <= 0 || m.mass <= 0) continue;
    // A line or a point has a singular inertia tensor: no defined rigid rotation to damp.
    const Real scale = m.inertia.trace();
    if (!(std::abs(m.inertia.determinant()) > Real(1e-12) * scale * scale * scale)) {
      continue;  // delta_omega stays zero
    }
    const Vec3 omega = m.inertia.inverse() * m.angular_momentum;
    const Vec3 damped = (m.inertia + kc * h * Mat3::Identity()).inverse() * m.angular_momentum;
    m.delta_omega = damped - omega;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (P.inverse_mass[i] == 0) continue;
    const ObjectMoments& m = moments[P.object[i]];
    if (model.objects[P.object[i]].angular_damping <= 0) continue;
    const Vec3 r = P.position[i] - m.mass_position / m.mass;
    P.velocity[i] += m.delta_omega.cross(r);
  }
}

}  // namespace imasim::physics
