#include "physics/constraint_system.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace imasim::physics {

namespace {

void require_particle(const Particles& particles, std::uint32_t i) {
  if (i >= particles.size()) {
    throw std::out_of_range("constraint refers to particle " + std::to_string(i) + " of " +
                            std::to_string(particles.size()));
  }
}

}  // namespace

DistanceHandle add_distance(ConstraintSystem& cs, const Particles& particles, std::uint32_t i,
                            std::uint32_t j, MaterialId material, Real compliance_scale) {
  require_particle(particles, i);
  require_particle(particles, j);
  if (i == j) throw std::invalid_argument("distance constraint needs two distinct particles");
  DistanceRow row;
  row.i = i;
  row.j = j;
  row.rest_length = (particles.rest_position[i] - particles.rest_position[j]).norm();
  row.compliance_scale = compliance_scale;
  row.material = material;
  return cs.distance.add(row, cs.band_of(particles, i));
}

DihedralHandle add_dihedral(ConstraintSystem& cs, const Particles& particles, std::uint32_t w0,
                            std::uint32_t w1, std::uint32_t a, std::uint32_t b, MaterialId material,
                            Real compliance_scale) {
  for (std::uint32_t p : {w0, w1, a, b})
    require_particle(particles, p);
  if (w0 == w1 || w0 == a || w0 == b || w1 == a || w1 == b || a == b) {
    throw std::invalid_argument("dihedral constraint needs four distinct particles");
  }
  DihedralRow row;
  row.p = {w0, w1, a, b};
  const auto& x0 = particles.rest_position;
  // Measured in double whatever Real is: the rest shape is set once and should be exact.
  const double rest = dihedral_angle<double>(x0[w0].cast<double>(), x0[w1].cast<double>(),
                                             x0[a].cast<double>(), x0[b].cast<double>());
  row.rest_cos = static_cast<Real>(std::cos(rest));
  row.rest_sin = static_cast<Real>(std::sin(rest));
  row.compliance_scale = compliance_scale;
  row.material = material;
  return cs.dihedral.add(row, cs.band_of(particles, a));
}

AttachmentHandle add_attachment(ConstraintSystem& cs, const Particles& particles, std::uint32_t i,
                                const Vec3& target, MaterialId material) {
  require_particle(particles, i);
  AttachmentRow row;
  row.i = i;
  row.target = target;
  row.material = material;
  return cs.attachment.add(row, cs.band_of(particles, i));
}

bool set_attachment_target(ConstraintSystem& cs, AttachmentHandle h, const Vec3& target) {
  AttachmentRow* row = cs.attachment.find(h);
  if (row == nullptr) return false;
  row->target = target;
  return true;
}

}  // namespace imasim::physics
