#include "tissue/strand_generator.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "geometry/uniform_grid.hpp"
#include "geometry/vertex_normals.hpp"
#include "math/angles.hpp"
#include "tissue/random.hpp"

namespace imasim::tissue {

namespace {

struct RayHit {
  bool hit = false;
  Real t = 0;
  std::uint32_t face = 0;
  std::array<Real, 3> bary = {1, 0, 0};
};

// Nearest intersection of origin + t dir, t in (0, max_t], with B (Moeller-Trumbore).
class RayCaster {
 public:
  RayCaster(const geometry::TriangleMesh& mesh, Real cell)
      : mesh_(mesh), grid_(boxes(mesh), cell) {}

  RayHit cast(const Vec3& origin, const Vec3& dir, Real max_t) {
    geometry::Box query(origin);
    query.extend(origin + max_t * dir);
    RayHit best;
    best.t = max_t;
    grid_.visit(query, visited_, stamp_, [&](std::uint32_t f) {
      const geometry::Triangle& t = mesh_.triangles[f];
      const Vec3 &a = mesh_.vertices[t[0]], &b = mesh_.vertices[t[1]], &c = mesh_.vertices[t[2]];
      const Vec3 e1 = b - a, e2 = c - a, p = dir.cross(e2);
      const Real det = e1.dot(p);
      if (std::abs(det) < Real(1e-18)) return;
      const Real inv = Real(1) / det;
      const Vec3 s = origin - a;
      const Real u = s.dot(p) * inv;
      if (u < 0 || u > 1) return;
      const Vec3 q = s.cross(e1);
      const Real v = dir.dot(q) * inv;
      if (v < 0 || u + v > 1) return;
      const Real tt = e2.dot(q) * inv;
      if (tt <= 0 || tt > best.t || (best.hit && tt == best.t && f > best.face)) return;
      best = {true, tt, f, {1 - u - v, u, v}};
    });
    return best;
  }

 private:
  static std::vector<geometry::Box> boxes(const geometry::TriangleMesh& m) {
    std::vector<geometry::Box> out;
    for (const auto& t : m.triangles) {
      out.push_back(geometry::triangle_box(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]));
    }
    return out;
  }
  const geometry::TriangleMesh& mesh_;
  geometry::UniformGrid grid_;
  std::vector<std::uint32_t> visited_;
  std::uint32_t stamp_ = 0;
};

Vec3 unit_normal(const geometry::TriangleMesh& m, std::uint32_t f) {
  const auto& t = m.triangles[f];
  return geometry::face_normal(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]).normalized();
}

Real mean_edge(const geometry::TriangleMesh& m) {
  Real sum = 0;
  for (const auto& t : m.triangles)
    sum += (m.vertices[t[1]] - m.vertices[t[0]]).norm();
  return sum / Real(m.triangles.size());
}

// A direction uniformly distributed over the cap of half-angle theta around unit n.
Vec3 direction_in_cone(const Vec3& n, Real theta, SplitMix64& rng) {
  const Real cos_a = 1 - rng.uniform() * (1 - std::cos(theta));
  const Real sin_a = std::sqrt(std::max(Real(0), 1 - cos_a * cos_a));
  const Real phi = 2 * kPi * rng.uniform();
  const Vec3 t1 = n.unitOrthogonal(), t2 = n.cross(t1);
  return cos_a * n + sin_a * (std::cos(phi) * t1 + std::sin(phi) * t2);
}

}  // namespace

Real centre_distance(const geometry::TriangleMesh& a, const geometry::TriangleMesh& b) {
  Vec3 ca = Vec3::Zero(), cb = Vec3::Zero();
  for (const Vec3& x : a.vertices)
    ca += x;
  for (const Vec3& x : b.vertices)
    cb += x;
  return (ca / Real(a.vertices.size()) - cb / Real(b.vertices.size())).norm();
}

StrandGeneration generate_strands(const geometry::TriangleMesh& a, const geometry::TriangleMesh& b,
                                  const StrandParams& p) {
  if (a.triangles.empty() || b.triangles.empty()) {
    throw std::invalid_argument("strands need two non-empty surfaces");
  }
  if (!(p.strands_per_face >= 0)) throw std::invalid_argument("strands_per_face must be >= 0");
  if (p.segments < 1) throw std::invalid_argument("segments per strand must be >= 1");
  if (!(p.max_angle >= 0 && p.max_angle < kPi / 2)) {
    throw std::invalid_argument("max_angle must be in [0, pi/2) rad");
  }
  StrandGeneration out;
  out.max_length = p.max_length > 0 ? p.max_length : centre_distance(a, b);  // eq. 6
  RayCaster caster(b, std::max(mean_edge(b), out.max_length / 8));
  SplitMix64 rng(p.seed);
  const Real whole = std::floor(p.strands_per_face), fraction = p.strands_per_face - whole;

  for (std::uint32_t f = 0; f < a.triangles.size(); ++f) {
    const auto& t = a.triangles[f];
    const Vec3 &v0 = a.vertices[t[0]], &v1 = a.vertices[t[1]], &v2 = a.vertices[t[2]];
    const Vec3 n = unit_normal(a, f);
    const RayHit axis = caster.cast((v0 + v1 + v2) / 3, n, out.max_length);
    if (!axis.hit || unit_normal(b, axis.face).dot(n) >= 0) continue;  // does not face B
    out.eligible_faces.push_back(f);
    const auto count = static_cast<std::uint32_t>(whole) + (rng.uniform() < fraction ? 1u : 0u);
    for (std::uint32_t s = 0; s < count; ++s) {
      bool made = false;
      for (std::uint32_t attempt = 0; attempt < p.attempts && !made; ++attempt) {
        // Uniform point on the face (folded square).
        Real r1 = rng.uniform(), r2 = rng.uniform();
        if (r1 + r2 > 1) r1 = 1 - r1, r2 = 1 - r2;
        const Vec3 start = v0 + r1 * (v1 - v0) + r2 * (v2 - v0);
        const Vec3 dir = direction_in_cone(n, p.max_angle, rng);
        const RayHit hit = caster.cast(start, dir, out.max_length);
        if (!hit.hit || unit_normal(b, hit.face).dot(dir) >= 0) continue;
        GeneratedStrand g;
        g.face_a = f;
        g.face_b = hit.face;
        g.bary_a = {1 - r1 - r2, r1, r2};
        g.bary_b = hit.bary;
        g.start = start;
        g.end = start + hit.t * dir;
        out.strands.push_back(g);
        made = true;
      }
      if (!made) ++out.dropped;
    }
  }
  return out;
}

}  // namespace imasim::tissue
