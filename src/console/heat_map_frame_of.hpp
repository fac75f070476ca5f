#pragma once
// The heat maps' frame of a surgical session (metrics/heat_map_frame.hpp, Fig. 13): the chest
// wall's tangent plane at the IMA's mid-course (origin at the IMA's midpoint, u along the IMA from
// its cranial to its caudal end, v = n x u across it, laterally; n the wall's outward normal
// there), the IMA's centerline, and outlines, in the scene's state at set-up, of the fascia (the
// boundary of its rest mesh), the fat (the convex hull of the strand particles' rest positions,
// projected) and the heart at its static phase (the convex hull of its projected vertices, its
// silhouette's outer edge).
#include <array>
#include <vector>

#include "metrics/heat_map_frame.hpp"
#include "session/surgical_session.hpp"

namespace imasim::console {

inline constexpr std::array<double, 3> kFasciaRgb{0.15, 0.35, 0.80};
inline constexpr std::array<double, 3> kFatRgb{0.20, 0.58, 0.18};
inline constexpr std::array<double, 3> kHeartRgb{0.35, 0.35, 0.35};

metrics::HeatMapFrame heat_map_frame_of(const session::SurgicalSession& session);

// The convex hull of plane points, counter-clockwise, without repeated or collinear points
// (Andrew's monotone chain); fewer than three distinct points come back as they are, deduplicated.
std::vector<metrics::PlanePoint> convex_hull(std::vector<metrics::PlanePoint> points);

// The longest closed loop of boundary edges (edges of one triangle only) of a triangle mesh, as
// vertex indices in order; empty when the mesh has no boundary.
std::vector<std::uint32_t> longest_boundary_loop(std::span<const geometry::Triangle> triangles);

}  // namespace imasim::console
