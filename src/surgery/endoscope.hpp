#pragma once
// The endoscope at the camera port
// ================================
// Robotic IMA harvesting views the chest through an endoscope inserted through the camera port
// on the left chest wall. Like the instrument arms (robotic_arm.hpp) the scope pivots about its
// port (remote centre of motion): its straight shaft always passes through the port, and the
// lens sits `insertion` beyond it along the shaft. The optics are 0 deg (the view looks straight
// down the shaft) or 30 deg (the view is tilted from the shaft by that angle).
//
// Conventions
// - Port: a position and a direction into the cavity (scene::Port's fields, passed as two
//   Vec3s so that surgery/ does not depend on scene/). The direction need not be unit.
// - Shaft: the port's direction, or `shaft_direction` when given (the scope pivoted about the
//   port); it must point into the cavity (less than 90 deg from the port's direction).
// - Eye (lens): port + insertion * shaft.
// - Reference up at roll 0: `reference_up` with its component along the shaft removed. The
//   default is cranial (-z of the scene frame, scene/anatomy.hpp), so the patient's head is at
//   the top of the image; ports on the chest wall aim medially across the IMA's course, never
//   along it. When `reference_up` is within ~1e-6 rad of the shaft's line, either way (no
//   usable component across it), the world axis least aligned with the shaft (x, then y, then
//   z on ties) stands in.
// - Roll turns that up about the shaft by `roll` (right-hand rule about the shaft direction);
//   the result is the tilt side.
// - View direction: 0 deg optics: the shaft; 30 deg optics: the shaft turned by the optics
//   angle towards the tilt side. The image up is perpendicular to the view, on the tilt side,
//   in the plane of shaft and view: for angled optics the shaft's axis appears below the image
//   centre, and rolling the scope turns both the view and the image about the shaft.
// - Camera frame: OpenGL convention: right-handed, looks along -z, +y is image up, +x image
//   right. `view` maps world to camera (the inverse of camera_to_world); `projection` is the
//   OpenGL perspective matrix (clip z in [-1, 1]; -1 at the near plane, +1 at the far plane).
//   Normalised device coordinates (NDC) are clip / w: x, y in [-1, 1] inside the field of view.
//   The vertical field of view spans NDC y in [-1, 1]; the horizontal extent is `aspect` times
//   the vertical one (in tangent), spanning NDC x in [-1, 1].
#include <optional>

#include "math/angles.hpp"
#include "math/pose.hpp"

namespace imasim::surgery {

using Mat4 = Eigen::Matrix<Real, 4, 4>;
using Vec2 = Eigen::Matrix<Real, 2, 1>;

struct EndoscopeParams {
  Real optics_angle = 0;        // view tilted from the shaft: 0 or 30 deg optics (unit: rad)
  Real insertion = Real(0.05);  // lens beyond the port along the shaft (unit: m)
  Real roll = 0;                // about the shaft; turns the tilt side and the image (unit: rad)
  // The scope pivoted about the port (need not be unit); empty: the port's direction.
  std::optional<Vec3> shaft_direction;
  Vec3 reference_up = -Vec3::UnitZ();  // image up at roll 0, made perpendicular to the shaft
  Real vertical_fov = degrees_to_radians(70);  // full angle, top to bottom edge (unit: rad)
  Real aspect = Real(16) / Real(9);            // image width / height (tangents of the half angles)
  Real near_plane = Real(0.002);               // (unit: m)
  Real far_plane = Real(0.3);                  // (unit: m)
};

// Throws std::invalid_argument naming the field: optics_angle in [0, 45 deg], insertion in
// [0.01, 0.3] m, vertical_fov in (0, 150 deg), aspect > 0, 0 < near_plane < far_plane, roll
// finite, shaft_direction and reference_up finite and non-zero.
void validate(const EndoscopeParams& params);

struct EndoscopeView {
  Pose camera_to_world;  // camera frame (OpenGL: looks along -z, +y image up) in the world
  Vec3 eye;              // lens position (unit: m)
  Vec3 view_direction;   // unit
  Vec3 up;               // unit, image up in the world
  Vec3 shaft;            // unit shaft direction, port towards lens
  Mat4 view;             // world -> camera, the inverse of camera_to_world
  Mat4 projection;       // OpenGL perspective, clip z in [-1, 1]
};

// The scope's camera through the port at `port_position` (m) entering along `port_direction`.
// Throws std::invalid_argument for invalid params, a zero or non-finite port direction, a
// non-finite port position, or a shaft that does not point into the cavity.
EndoscopeView endoscope_view(const Vec3& port_position, const Vec3& port_direction,
                             const EndoscopeParams& params);

// OpenGL perspective matrix (right-handed, looks along -z, clip z in [-1, 1]).
Mat4 perspective(Real vertical_fov, Real aspect, Real near_plane, Real far_plane);

// NDC (x, y) of a world point; empty when it lies nearer than the near plane (or behind the
// eye) or beyond the far plane. Points beside the field of view give |x| or |y| > 1.
std::optional<Vec2> project_to_ndc(const EndoscopeView& view, const Vec3& world_point);

// Inside the view frustum (boundary included).
bool in_view(const EndoscopeView& view, const Vec3& world_point);

}  // namespace imasim::surgery
