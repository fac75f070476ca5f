#pragma once
// What the scripted operator sees of the scene before it starts (the description at rest, never
// the tissue's state): the IMA segment to harvest, a frame along it (tangent, the wall's outward
// normal, the direction across the vessel away from the heart), the fascia's plane, the heart at
// its static phase and how far the heart moves over a beat under the segment.
#include <vector>

#include "session/surgical_session.hpp"

namespace imasim::autopilot {

struct WorkingFrame {
  std::vector<Vec3> segment;  // the harvested centerline, resampled every mm (unit: m)
  std::vector<Real> arc;      // arc length of each segment point from its proximal end (unit: m)
  Vec3 wall_normal = Vec3::UnitY();  // out of the cavity, into the wall, at the segment's middle
  Vec3 away = Vec3::UnitX();         // across the vessel, away from the heart's side
  Real fascia_depth = 0;    // from the vessel's centre to the fascia along -wall_normal (unit: m)
  Real wall_height = 0;     // from the vessel's centre to the wall along +wall_normal (unit: m)
  std::vector<Vec3> heart;  // vertices at the static phase (unit: m)
  std::vector<std::array<std::uint32_t, 3>> heart_triangles;
  Real heart_excursion = 0;  // largest heart displacement near the segment over a beat (unit: m)
  Vec3 forceps_port = Vec3::Zero(), hook_port = Vec3::Zero();  // pivots (unit: m)
  Pose forceps_start, hook_start;                              // the tools at set-up
  // The hook arm's kinematics (the port's pivot, insertion range, the wrist's reach): a surgeon
  // knows how far an instrument's wrist bends.
  surgery::ArmParams hook_arm;

  // The centerline point and unit tangent at arc length s (clamped to the segment).
  Vec3 point_at(Real s) const;
  Vec3 tangent_at(Real s) const;
  Real length() const { return arc.empty() ? Real(0) : arc.back(); }
  // Distance from the heart's surface at its static phase (unsigned: the procedural heart's two
  // chambers overlap, so the nearest triangle cannot tell inside from outside) (unit: m).
  Real heart_distance(const Vec3& p) const;
};

// Distance from a polyline (unit: m); infinite for fewer than two points.
Real distance_to_segment(const Vec3& p, const std::vector<Vec3>& line);

// Throws std::invalid_argument when the IMA is shorter than `segment_length`.
WorkingFrame make_working_frame(const session::SurgicalSession& session, Real segment_length);

}  // namespace imasim::autopilot
