#include "geometry/tube.hpp"

#include <cmath>
#include <stdexcept>

#include "math/angles.hpp"

namespace imasim::geometry {

std::vector<Vec3> resample_polyline(const std::vector<Vec3>& polyline, std::uint32_t count) {
  std::vector<Real> s(polyline.size(), Real(0));  // arc length at each polyline vertex
  for (std::size_t i = 1; i < polyline.size(); ++i) {
    s[i] = s[i - 1] + (polyline[i] - polyline[i - 1]).norm();
  }
  if (polyline.size() < 2 || !(s.back() > 0)) {
    throw std::invalid_argument("a centerline needs at least two distinct points");
  }
  std::vector<Vec3> out;
  out.reserve(count);
  std::size_t seg = 0;
  for (std::uint32_t k = 0; k < count; ++k) {
    const Real target = s.back() * Real(k) / Real(count - 1);
    while (seg + 2 < polyline.size() && s[seg + 1] < target)
      ++seg;
    const Real len = s[seg + 1] - s[seg];
    const Real t = len > 0 ? std::clamp((target - s[seg]) / len, Real(0), Real(1)) : Real(0);
    out.push_back((1 - t) * polyline[seg] + t * polyline[seg + 1]);
  }
  return out;
}

namespace {

// Quads between consecutive rows of a (columns x rows) vertex lattice, two triangles each;
// `wrap` closes the columns into a ring. Winding (a, b, c) with (b - a) x (c - a) along
// (column direction) x (row direction).
void add_lattice_faces(TriangleMesh& mesh, std::uint32_t columns, std::uint32_t rows, bool wrap) {
  const std::uint32_t quads = wrap ? columns : columns - 1;
  for (std::uint32_t r = 0; r + 1 < rows; ++r) {
    for (std::uint32_t c = 0; c < quads; ++c) {
      const std::uint32_t c1 = (c + 1) % columns;
      const std::uint32_t a = r * columns + c, b = r * columns + c1;
      const std::uint32_t d = (r + 1) * columns + c, e = (r + 1) * columns + c1;
      mesh.triangles.push_back({a, b, e});
      mesh.triangles.push_back({a, e, d});
    }
  }
}

}  // namespace

TriangleMesh make_tube(const TubeSpec& spec) {
  if (spec.rings < 2 || spec.ring_segments < 3) {
    throw std::invalid_argument("a tube needs at least 2 rings of 3 segments");
  }
  if (!(spec.radius > 0)) throw std::invalid_argument("a tube needs a positive radius");
  const std::vector<Vec3> c = resample_polyline(spec.centerline, spec.rings);
  TriangleMesh mesh;
  mesh.vertices.reserve(std::size_t(spec.rings) * spec.ring_segments);
  // Initial normal: any unit vector perpendicular to the first tangent.
  Vec3 tangent = (c[1] - c[0]).normalized();
  Vec3 normal = tangent.unitOrthogonal();
  for (std::uint32_t r = 0; r < spec.rings; ++r) {
    const Vec3 next_tangent =
        r + 1 < spec.rings ? (c[r + 1] - c[r]).normalized() : (c[r] - c[r - 1]).normalized();
    const Vec3 t = r == 0 ? tangent : (tangent + next_tangent).normalized();
    // Parallel transport: remove the normal's component along the new tangent.
    normal = (normal - normal.dot(t) * t).normalized();
    const Vec3 binormal = t.cross(normal);
    for (std::uint32_t k = 0; k < spec.ring_segments; ++k) {
      const Real phi = 2 * kPi * Real(k) / Real(spec.ring_segments);
      mesh.vertices.push_back(c[r] +
                              spec.radius * (std::cos(phi) * normal + std::sin(phi) * binormal));
    }
    tangent = next_tangent;
  }
  // Columns run around the ring (normal -> binormal), rows along the tangent: column x row
  // direction = binormal x tangent = normal, outwards.
  add_lattice_faces(mesh, spec.ring_segments, spec.rings, true);
  return mesh;
}

TriangleMesh make_cylinder_patch(const CylinderPatchSpec& spec) {
  if (spec.nu < 2 || spec.nv < 2 || !(spec.radius > 0) || !(spec.length > 0) ||
      !(spec.angle1 > spec.angle0)) {
    throw std::invalid_argument(
        "cylinder patch needs nu, nv >= 2, a positive radius and length "
        "and angle1 > angle0");
  }
  const Vec3 axis = spec.axis.normalized();
  const Vec3 ref = (spec.reference - spec.reference.dot(axis) * axis).normalized();
  const Vec3 side = axis.cross(ref);
  TriangleMesh mesh;
  for (std::uint32_t v = 0; v < spec.nv; ++v) {
    const Real along = spec.length * Real(v) / Real(spec.nv - 1);
    for (std::uint32_t u = 0; u < spec.nu; ++u) {
      const Real a = spec.angle0 + (spec.angle1 - spec.angle0) * Real(u) / Real(spec.nu - 1);
      mesh.vertices.push_back(spec.origin + along * axis +
                              spec.radius * (std::cos(a) * ref + std::sin(a) * side));
    }
  }
  // Columns turn about the axis, rows run along it: (column x row) = side-ish x axis points
  // outwards; flip the winding so normals face the axis.
  add_lattice_faces(mesh, spec.nu, spec.nv, false);
  for (Triangle& t : mesh.triangles)
    std::swap(t[1], t[2]);
  return mesh;
}

}  // namespace imasim::geometry
