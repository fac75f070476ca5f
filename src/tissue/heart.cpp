#include "tissue/heart.hpp"

#include <cmath>
#include <stdexcept>

#include "geometry/mesh_checks.hpp"
#include "math/angles.hpp"
#include "math/pose.hpp"

namespace imasim::tissue {

namespace {

// A closed spheroid lattice around the local z axis (base pole at z = +1/2, apex at z = -1/2 of
// a unit length, unit radius): rings x segments vertices plus the two poles; outward normals.
geometry::TriangleMesh unit_spheroid(std::uint32_t rings, std::uint32_t segments) {
  geometry::TriangleMesh m;
  m.vertices.emplace_back(0, 0, Real(0.5));  // base pole
  for (std::uint32_t r = 1; r <= rings; ++r) {
    const Real polar = kPi * Real(r) / Real(rings + 1);
    for (std::uint32_t s = 0; s < segments; ++s) {
      const Real az = 2 * kPi * Real(s) / Real(segments);
      m.vertices.emplace_back(std::sin(polar) * std::cos(az), std::sin(polar) * std::sin(az),
                              Real(0.5) * std::cos(polar));
    }
  }
  m.vertices.emplace_back(0, 0, Real(-0.5));  // apex pole
  const auto ring = [&](std::uint32_t r, std::uint32_t s) {
    return 1 + (r - 1) * segments + s % segments;
  };
  const auto apex = static_cast<std::uint32_t>(m.vertices.size() - 1);
  for (std::uint32_t s = 0; s < segments; ++s) {
    m.triangles.push_back({0, ring(1, s), ring(1, s + 1)});
    for (std::uint32_t r = 1; r < rings; ++r) {
      m.triangles.push_back({ring(r, s), ring(r + 1, s), ring(r + 1, s + 1)});
      m.triangles.push_back({ring(r, s), ring(r + 1, s + 1), ring(r, s + 1)});
    }
    m.triangles.push_back({ring(rings, s), apex, ring(rings, s + 1)});
  }
  return m;
}

Real smooth_step(Real x) {
  return (1 - std::cos(kPi * x)) / 2;
}  // C1, 0 -> 1

}  // namespace

CardiacPhases cardiac_phases(const HeartParams& p) {
  const Real s = p.systole_fraction, d = 1 - s;
  return {s, s + kRapidFillingEnd * d, s + kAtrialStart * d, s + kAtrialEnd * d};
}

Real heart_volume_fraction(const HeartParams& p, Real t) {
  t -= std::floor(t);
  const Real ef = p.ejection_fraction;
  const CardiacPhases c = cardiac_phases(p);
  if (t < c.end_systole) return 1 - ef * smooth_step(t / c.end_systole);  // ejection
  if (t >= c.atrial_end) return 1;                                        // until the R wave
  // Diastasis' slope (volume per cycle), which rapid filling ends with and atrial contraction
  // starts with: the pieces join C1.
  const Real g = kDiastasisShare * ef / (c.atrial_start - c.end_rapid_filling);
  const Real v_filled = 1 - ef + kRapidFillingShare * ef;  // at the end of rapid filling
  if (t < c.end_rapid_filling) {
    // Hermite from (1 - EF, slope 0) to (v_filled, slope g); rising throughout because
    // g L = 0.04 EF < 3 * 0.75 EF, whatever s.
    const Real L = c.end_rapid_filling - c.end_systole, u = (t - c.end_systole) / L;
    return 1 - ef + kRapidFillingShare * ef * u * u * (3 - 2 * u) + g * L * u * u * (u - 1);
  }
  if (t < c.atrial_start) return v_filled + g * (t - c.end_rapid_filling);  // diastasis
  // Hermite from (v_filled + diastasis' share, slope g) to (1, slope 0); rising throughout
  // because g L = 0.022 EF < 3 * 0.22 EF.
  const Real L = c.atrial_end - c.atrial_start, u = (t - c.atrial_start) / L;
  const Real v_atrial = v_filled + kDiastasisShare * ef;
  return v_atrial + kAtrialShare * ef * u * u * (3 - 2 * u) + g * L * u * (1 - u) * (1 - u);
}

HeartModel make_procedural_heart(const HeartParams& p) {
  if (p.phases < 3) throw std::invalid_argument("heart: at least 3 phases");
  if (!(p.ejection_fraction > 0 && p.ejection_fraction < 1)) {
    throw std::invalid_argument("heart: ejection_fraction must be in (0, 1)");
  }
  if (!(p.systole_fraction > 0 && p.systole_fraction < 1)) {
    throw std::invalid_argument("heart: systole_fraction must be in (0, 1)");
  }
  const geometry::TriangleMesh unit = unit_spheroid(p.rings, p.segments);
  const Vec3 axis = p.long_axis.normalized();
  const Vec3 lateral = (p.lateral - p.lateral.dot(axis) * axis).normalized();
  Mat3 frame;  // local (x, y, z) -> world: z along the long axis (base -> apex is local -z)
  frame.col(0) = lateral;
  frame.col(1) = (-axis).cross(lateral);
  frame.col(2) = -axis;

  HeartModel heart;
  struct Ventricle {
    Vec3 centre;
    Real length, radius;
  };
  const Ventricle ventricles[2] = {{p.centre, p.lv_length, p.lv_radius},
                                   {p.centre + p.rv_offset * lateral, p.rv_length, p.rv_radius}};
  for (const Ventricle& v : ventricles) {
    (void)v;
    const auto base = static_cast<std::uint32_t>(heart.topology.vertices.size());
    heart.component_start.push_back(base);
    heart.component_triangle_start.push_back(
        static_cast<std::uint32_t>(heart.topology.triangles.size()));
    for (const Vec3& x : unit.vertices)
      heart.topology.vertices.push_back(x);
    for (const auto& t : unit.triangles)
      heart.topology.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
  }
  heart.component_start.push_back(static_cast<std::uint32_t>(heart.topology.vertices.size()));
  heart.component_triangle_start.push_back(
      static_cast<std::uint32_t>(heart.topology.triangles.size()));

  heart.keyframes.resize(p.phases);
  for (std::uint32_t k = 0; k < p.phases; ++k) {
    const Real t = Real(k) / Real(p.phases);
    const Real volume = heart_volume_fraction(p, t);
    const Real contraction = (1 - volume) / p.ejection_fraction;  // 0 at ED, 1 at ES
    const Real length_scale = 1 - p.longitudinal_shortening * contraction;
    const Real radial_scale = std::sqrt(volume / length_scale);  // volume ~ r^2 L
    std::vector<Vec3>& out = heart.keyframes[k];
    for (std::uint32_t c = 0; c < 2; ++c) {
      const Ventricle& v = ventricles[c];
      // The base (local z = +1/2) stays put; the ventricle shortens towards it and the apex
      // twists against it in proportion to the distance from the base.
      const Vec3 base_point = v.centre + frame * Vec3(0, 0, v.length / 2);
      for (std::uint32_t i = heart.component_start[c]; i < heart.component_start[c + 1]; ++i) {
        const Vec3& u = heart.topology.vertices[i];
        const Real from_base = Real(0.5) - u.z();  // 0 at the base, 1 at the apex
        const Real angle = p.twist * contraction * from_base;
        const Real ca = std::cos(angle), sa = std::sin(angle);
        const Vec3 radial(v.radius * radial_scale * (ca * u.x() - sa * u.y()),
                          v.radius * radial_scale * (sa * u.x() + ca * u.y()), 0);
        const Vec3 along(0, 0, -from_base * v.length * length_scale);
        out.push_back(base_point + frame * (radial + along));
      }
    }
  }
  heart.topology.vertices = heart.keyframes[0];
  return heart;
}

namespace {

// Where cycle fraction t falls among the keyframes: the four frames of its Catmull-Rom span and
// the share u in [0, 1) of the way from the second to the third.
struct KeyframeSpan {
  const std::vector<Vec3>*p0, *p1, *p2, *p3;
  Real u;
};

KeyframeSpan keyframe_span(const HeartModel& heart, Real t) {
  const auto n = static_cast<std::int64_t>(heart.keyframes.size());
  const Real x = (t - std::floor(t)) * Real(n);
  const auto k = static_cast<std::int64_t>(std::floor(x));
  auto frame = [&](std::int64_t i) {
    return &heart.keyframes[static_cast<std::size_t>(((i % n) + n) % n)];
  };
  return {frame(k - 1), frame(k), frame(k + 1), frame(k + 2), x - Real(k)};
}

}  // namespace

void interpolate_heart(const HeartModel& heart, Real t, std::vector<Vec3>& out) {
  const KeyframeSpan s = keyframe_span(heart, t);
  const Real u = s.u, u2 = u * u, u3 = u2 * u;
  // Uniform Catmull-Rom: C1, through the keyframes, tangents (p_{k+1} - p_{k-1}) / 2.
  const Real a = (-u3 + 2 * u2 - u) / 2, b = (3 * u3 - 5 * u2 + 2) / 2;
  const Real c = (-3 * u3 + 4 * u2 + u) / 2, d = (u3 - u2) / 2;
  const auto &p0 = *s.p0, &p1 = *s.p1, &p2 = *s.p2, &p3 = *s.p3;
  out.resize(p1.size());
  for (std::size_t i = 0; i < p1.size(); ++i)
    out[i] = a * p0[i] + b * p1[i] + c * p2[i] + d * p3[i];
}

Vec3 heart_vertex_rate(const HeartModel& heart, Real t, std::uint32_t vertex) {
  const KeyframeSpan s = keyframe_span(heart, t);
  const Real u = s.u, u2 = u * u;
  // The basis of interpolate_heart differentiated in u; du/dt = n, the keyframe count.
  const Real a = (-3 * u2 + 4 * u - 1) / 2, b = (9 * u2 - 10 * u) / 2;
  const Real c = (-9 * u2 + 8 * u + 1) / 2, d = (3 * u2 - 2 * u) / 2;
  const Real n = Real(heart.keyframes.size());
  return n *
         (a * (*s.p0)[vertex] + b * (*s.p1)[vertex] + c * (*s.p2)[vertex] + d * (*s.p3)[vertex]);
}

Real component_volume(const HeartModel& heart, const std::vector<Vec3>& x, std::uint32_t c) {
  const std::uint32_t first = heart.component_triangle_start[c];
  return geometry::enclosed_volume(
      x, std::span(heart.topology.triangles)
             .subspan(first, heart.component_triangle_start[c + 1] - first));
}

Real HeartPlayback::cycles_per_second() const {
  return beating ? heart_rate_bpm / Real(60) : Real(0);
}

Real HeartPlayback::phase_at(double time_s) const {
  // The beating heart starts at the static phase, so the shape at t = 0 is the same in both
  // modes and the drive of the anchors (measured from that shape) starts from zero.
  const double cycles =
      double(static_phase) + (beating ? time_s * double(heart_rate_bpm) / 60.0 : 0.0);
  return Real(cycles - std::floor(cycles));
}

}  // namespace imasim::tissue
