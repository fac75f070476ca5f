#pragma once
// Closest points to a point: on a segment, and on a triangle as barycentric coordinates
// (Voronoi-region method).
#include <algorithm>
#include <array>

#include "math/types.hpp"

namespace imasim::geometry {

// The parameter t in [0, 1] of the point of segment a-b closest to p (0 for a degenerate one).
inline Real closest_segment_parameter(const Vec3& p, const Vec3& a, const Vec3& b) {
  const Vec3 ab = b - a;
  const Real length2 = ab.squaredNorm();
  return length2 > 0 ? std::clamp((p - a).dot(ab) / length2, Real(0), Real(1)) : Real(0);
}

struct TrianglePoint {
  std::array<Real, 3> bary = {1, 0, 0};  // weights of a, b, c; sum 1, each >= 0
  Vec3 point = Vec3::Zero();
  Real distance2 = 0;  // squared distance from the query (unit: m^2)
};

inline TrianglePoint closest_point_on_triangle(const Vec3& p, const Vec3& a, const Vec3& b,
                                               const Vec3& c) {
  auto make = [&](Real u, Real v, Real w) {
    TrianglePoint r;
    r.bary = {u, v, w};
    r.point = u * a + v * b + w * c;
    r.distance2 = (p - r.point).squaredNorm();
    return r;
  };
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const Real d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return make(1, 0, 0);
  const Vec3 bp = p - b;
  const Real d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return make(0, 1, 0);
  const Real vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) {
    const Real v = d1 / (d1 - d3);
    return make(1 - v, v, 0);
  }
  const Vec3 cp = p - c;
  const Real d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return make(0, 0, 1);
  const Real vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) {
    const Real w = d2 / (d2 - d6);
    return make(1 - w, 0, w);
  }
  const Real va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) {
    const Real w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    return make(0, 1 - w, w);
  }
  const Real denom = Real(1) / (va + vb + vc);
  const Real v = vb * denom, w = vc * denom;
  return make(1 - v - w, v, w);
}

}  // namespace imasim::geometry
