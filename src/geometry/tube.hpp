#pragma once
// Tube and cylinder-patch generators.
#include <cstdint>
#include <vector>

#include "geometry/triangle_mesh.hpp"

namespace imasim::geometry {

// An open tube of `radius` around a centerline polyline, resampled to `rings` rings equally
// spaced in arc length, each of `ring_segments` vertices. Vertex (ring r, segment k) has index
// r * ring_segments + k; frames are carried along the centerline by parallel transport, so the
// tube does not twist. Normals point outwards. Throws std::invalid_argument for fewer than two
// distinct centerline points, rings < 2, ring_segments < 3 or a non-positive radius.
struct TubeSpec {
  std::vector<Vec3> centerline;  // (unit: m)
  Real radius = Real(0.00125);   // (unit: m)
  std::uint32_t ring_segments = 6;
  std::uint32_t rings = 20;
};
TriangleMesh make_tube(const TubeSpec& spec);

// The centerline resampled at `count` points equally spaced in arc length.
std::vector<Vec3> resample_polyline(const std::vector<Vec3>& polyline, std::uint32_t count);

// A patch of a cylinder: axis through `origin` along `axis`, `radius`, the angular span
// [angle0, angle1] (rad, measured from `reference`, a unit vector normal to the axis, turning
// right-handed about the axis), `length` along the axis; nu x nv vertices (around x along).
// Normals point towards the axis (the inside of the chest wall faces the thoracic cavity).
struct CylinderPatchSpec {
  Vec3 origin = Vec3::Zero();
  Vec3 axis = Vec3::UnitZ();
  Vec3 reference = Vec3::UnitY();
  Real radius = Real(0.1);
  Real angle0 = Real(-0.5), angle1 = Real(0.5);
  Real length = Real(0.15);
  std::uint32_t nu = 12, nv = 16;
};
TriangleMesh make_cylinder_patch(const CylinderPatchSpec& spec);

}  // namespace imasim::geometry
