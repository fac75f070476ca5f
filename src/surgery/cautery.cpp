#include "surgery/cautery.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/closest_point.hpp"
#include "math/angles.hpp"

namespace imasim::surgery {
const char* to_string(PedalMode mode) {
  switch (mode) {
    case PedalMode::off:
      return "off";
    case PedalMode::cut:
      return "cut";
    case PedalMode::coag:
      return "coag";
  }
  return "unknown";
}

void validate(const CauteryParams& p) {
  auto require = [](bool ok, const char* what) {
    if (!ok) throw std::invalid_argument(std::string("cautery: ") + what);
  };
  require(p.power >= 30 && p.power <= 50, "power must be within [30, 50] W");
  require(p.electrode_length > 0, "electrode_length must be > 0");
  require(p.contact_radius > 0, "contact_radius must be > 0");
  require(p.spread_radius >= p.contact_radius, "spread_radius must be >= contact_radius");
  require(p.cut_heat_fraction >= 0 && p.cut_heat_fraction <= 1, "cut_heat_fraction in [0, 1]");
  require(p.coag_heat_fraction >= 0 && p.coag_heat_fraction <= 1, "coag_heat_fraction in [0, 1]");
  require(p.specific_heat > 0, "specific_heat must be > 0");
  require(p.density > 0, "density must be > 0");
  require(p.thermal_diffusivity >= 0 && std::isfinite(p.thermal_diffusivity),
          "thermal_diffusivity must be >= 0");
  require(p.coagulation_rise > 0 && p.injury_rise > 0, "temperature rises must be > 0");
  require(p.coagulated_compliance_factor > 0 && p.coagulated_compliance_factor <= 1,
          "coagulated_compliance_factor in (0, 1]");
}

CauteryState make_cautery_state(tissue::TissueWorld& w, const CauteryParams& params,
                                const std::vector<physics::ObjectId>& heatable,
                                physics::ObjectId ima_object) {
  validate(params);
  CauteryState s;
  const std::size_t n = w.state.particles.size();
  s.rise.assign(n, Real(0));
  s.coagulated.assign(n, 0);
  s.injured.assign(n, 0);
  s.heatable.assign(w.model.objects.size(), 0);
  for (physics::ObjectId o : heatable)
    s.heatable.at(o) = 1;
  s.ima_object = ima_object;
  const std::size_t materials = w.model.materials.size();
  for (std::size_t m = 0; m < materials; ++m) {
    physics::ConstraintMaterial stiff = w.model.materials[m];
    stiff.compliance *= params.coagulated_compliance_factor;
    s.coagulated_material.push_back(w.model.add_material(stiff));
  }
  s.reached.reserve(n);
  s.weight.reserve(n);
  return s;
}

Real cooling_time(const CauteryParams& p) {
  const Real sigma = p.spread_radius / 2;
  if (p.thermal_diffusivity <= 0) return std::numeric_limits<Real>::infinity();
  return sigma * sigma / (4 * p.thermal_diffusivity);  // tau = sigma^2 / (4 alpha) (unit: s)
}

void cool_tissue(const CauteryParams& params, Real dt, CauteryState& s) {
  if (s.dose == 0) return;  // never heated: nothing to cool
  const Real keep = std::exp(-dt / cooling_time(params));
  // Rises below this are gone (and stay out of the subnormal range, where arithmetic is slow).
  constexpr Real kNegligible = Real(1e-9);  // (unit: K)
  for (Real& rise : s.rise)
    rise = rise * keep < kNegligible ? Real(0) : rise * keep;
}

CauteryStep apply_cautery(tissue::TissueWorld& w, const CauteryParams& params, PedalMode pedal,
                          const Vec3& a, const Vec3& b, Real dt, CauteryState& s) {
  CauteryStep step;
  step.active = pedal != PedalMode::off;
  // No current, no heat: the tissue is only searched while the pedal is pressed.
  if (!step.active) return step;
  const physics::Particles& P = w.state.particles;
  s.reached.clear();
  s.weight.clear();
  const Real sigma = params.spread_radius / 2;
  const Vec3 lo = a.cwiseMin(b).array() - params.spread_radius;
  const Vec3 hi = a.cwiseMax(b).array() + params.spread_radius;
  for (std::uint32_t i = 0; i < P.size(); ++i) {
    const Vec3& x = P.position[i];
    if ((x.array() < lo.array()).any() || (x.array() > hi.array()).any()) continue;
    if (P.is_fixed(i) || !s.heatable[P.object[i]]) continue;
    const Real r = (x - (a + geometry::closest_segment_parameter(x, a, b) * (b - a))).norm();
    if (r <= params.contact_radius) ++step.touching;
    if (r > params.spread_radius) continue;
    s.reached.push_back(i);
    s.weight.push_back(std::exp(-(r / sigma) * (r / sigma)));
  }
  // Heat only while the electrode touches tissue.
  if (step.touching == 0) return step;
  const Real fraction =
      pedal == PedalMode::cut ? params.cut_heat_fraction : params.coag_heat_fraction;
  step.energy = fraction * params.power * dt;  // E = eta P dt (unit: J)
  s.dose += step.energy;
  // The line source's volume, pi sigma^2 (L + sqrt(pi) sigma) (unit: m^3), and the tissue's
  // heat capacity per volume rho c (unit: J/(m^3 K)).
  const Real length = (b - a).norm();
  const Real volume = kPi * sigma * sigma * (length + std::sqrt(kPi) * sigma);
  const Real peak_rise = step.energy / (volume * params.density * params.specific_heat);
  for (std::size_t k = 0; k < s.reached.size(); ++k) {
    const std::uint32_t i = s.reached[k];
    s.rise[i] += peak_rise * s.weight[k];  // q(r) / (rho c) (unit: K)
    const Real rise = s.rise[i];
    if (!s.coagulated[i] && rise >= params.coagulation_rise) {
      s.coagulated[i] = 1;
      ++s.coagulated_count;
      ++step.coagulated;
    }
    if (P.object[i] == s.ima_object) {
      step.max_ima_rise = std::max(step.max_ima_rise, rise);
      if (!s.injured[i] && rise >= params.injury_rise) {
        s.injured[i] = 1;
        ++step.injured;
      }
    }
  }
  if (step.coagulated > 0) stiffen_coagulated(w, s);
  return step;
}

void inherit_cautery_state(const tissue::TissueWorld& w, const CauteryParams& params,
                           std::uint32_t mesh, std::uint32_t first_new_vertex,
                           std::span<const tissue::NewVertex> vertices, CauteryState& s) {
  const physics::Particles& P = w.state.particles;
  if (s.rise.size() < P.size()) {  // particles added since set-up (not the spares: reserved)
    s.rise.resize(P.size(), 0);
    s.coagulated.resize(P.size(), 0);
    s.injured.resize(P.size(), 0);
  }
  const std::uint32_t first = w.meshes[mesh].first_particle;
  for (std::size_t k = 0; k < vertices.size(); ++k) {
    const tissue::NewVertex& nv = vertices[k];
    const std::uint32_t a = first + nv.a, b = first + nv.b;
    const std::uint32_t i = first + first_new_vertex + static_cast<std::uint32_t>(k);
    // The same weights as the position (topology_change.cpp): a copy (a == b) gets exactly its
    // parent's rise.
    s.rise[i] = (1 - nv.t) * s.rise[a] + nv.t * s.rise[b];
    const bool coagulated =
        (s.coagulated[a] && s.coagulated[b]) || s.rise[i] >= params.coagulation_rise;
    if (coagulated && !s.coagulated[i]) ++s.coagulated_count;
    s.coagulated[i] = coagulated ? 1 : 0;
    s.injured[i] = P.object[i] == s.ima_object &&
                           ((s.injured[a] && s.injured[b]) || s.rise[i] >= params.injury_rise)
                       ? 1
                       : 0;
  }
}

void stiffen_coagulated(tissue::TissueWorld& w, CauteryState& s) {
  if (s.coagulated_count == 0) return;  // nothing to stiffen: no pass over the constraints
  if (s.coagulated.size() < w.state.particles.size()) {
    s.coagulated.resize(w.state.particles.size(), 0);  // particles added since set-up
  }
  for (auto& group : w.state.constraints.distance.groups()) {
    for (physics::DistanceRow& r : group.rows) {
      if (!s.coagulated[r.i] && !s.coagulated[r.j]) continue;
      if (r.material < s.coagulated_material.size()) r.material = s.coagulated_material[r.material];
    }
  }
}

Vec3 coagulation_colour(const Vec3& base, Real rise, const CauteryParams& params) {
  const Vec3 coagulated(Real(0.82), Real(0.72), Real(0.55));
  const Real s = std::clamp(rise / params.coagulation_rise, Real(0), Real(1));
  return (1 - s) * base + s * coagulated;
}

}  // namespace imasim::surgery
