#pragma once
// The Spatial Asymmetry Index (eq. 20 of Wang et al., "A virtual simulation platform for robotic
// internal mammary artery harvesting", the paper in ../shared/paper) as SPEC S6 reads it:
//   SAI = (1/n) sum_i sign_i |d_i| / R,
// d_i the perpendicular distance from the tool tip at sample i (60 Hz) to the IMA centerline,
// sign_i its side: -1 toward the heart, +1 away from it (0 on the centerline), R = 2 mm. The heart
// side at a centerline point is the direction to the nearest heart surface point, taken
// perpendicular to the centerline there. Positive: the tool kept away from the heart.
#include <span>
#include <stdexcept>
#include <vector>

#include "geometry/triangle_mesh.hpp"
#include "math/types.hpp"

namespace imasim::metrics {

inline constexpr Real kSaiRadius = Real(0.002);  // R of eq. 20 (unit: m)
// Beyond what a chest holds: a tool tip this far from the centerline, or a centerline this long,
// is a file in other units or a broken one, and its score would be meaningless (unit: m).
inline constexpr Real kMaxSaiDistance = 10;
// A heart surface's area outside these is not a heart in metres (unit: m^2).
inline constexpr Real kMinHeartArea = Real(1e-6), kMaxHeartArea = 10;

class SaiError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// The centerline with the heart's side at each of its points: unit vectors perpendicular to the
// centerline's tangent, pointing toward the nearest point of the heart's surface.
struct SideReference {
  std::vector<Vec3> centerline;  // polyline, >= 2 distinct points (unit: m)
  std::vector<Vec3> heart_side;  // one per centerline point
};

// Throws SaiError for fewer than two points, repeated consecutive points, points more than
// kMaxSaiDistance apart, an empty heart, a heart with no triangle of any area or an area outside
// [kMinHeartArea, kMaxHeartArea], or a heart surface that touches the centerline (no side can be
// told). Triangles without an area are left out of the nearest-point search.
SideReference make_side_reference(std::span<const Vec3> centerline,
                                  const geometry::TriangleMesh& heart);

struct SaiResult {
  Real sai = 0;                  // eq. 20 (-)
  std::size_t samples = 0;       // n
  Real mean_distance = 0;        // mean |d_i| (unit: m)
  Real heart_side_fraction = 0;  // share of samples on the heart's side (-)
};

// One tool's trajectory; R > 0 (SaiError otherwise, or for a non-finite sample or one more than
// kMaxSaiDistance from the centerline). No samples: all zero (`imasim sai` refuses them).
SaiResult spatial_asymmetry(const SideReference& reference, std::span<const Vec3> tips,
                            Real radius = kSaiRadius);

// One sample: its perpendicular distance (unit: m) and side (-1, 0, +1).
struct SideDistance {
  Real distance = 0;
  int side = 0;
};
SideDistance side_distance(const SideReference& reference, const Vec3& tip);

}  // namespace imasim::metrics
