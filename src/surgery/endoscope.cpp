#include "surgery/endoscope.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace imasim::surgery {
namespace {

void require(bool ok, const char* field, const char* what) {
  if (!ok) throw std::invalid_argument(std::string("endoscope: ") + field + " " + what);
}

bool finite_nonzero(const Vec3& v) {
  return v.allFinite() && v.squaredNorm() > 0;
}

// The unit roll-0 up of the scope: `reference` without its component along the unit `shaft`.
Vec3 reference_across(const Vec3& shaft, const Vec3& reference) {
  const Vec3 r = reference.normalized();
  const Vec3 across = r - r.dot(shaft) * shaft;
  // Below ~1e-6 rad from the shaft the projection's direction is mostly rounding and swings
  // wildly with tiny pivots; the world axis least aligned with the shaft is always usable.
  if (across.norm() > Real(1e-6)) return across.normalized();
  Eigen::Index axis = 0;
  shaft.cwiseAbs().minCoeff(&axis);
  const Vec3 e = Vec3::Unit(axis);
  return (e - e.dot(shaft) * shaft).normalized();
}

}  // namespace

void validate(const EndoscopeParams& p) {
  // Negated comparisons so that NaN fails every check.
  require(p.optics_angle >= 0 && p.optics_angle <= degrees_to_radians(45), "optics_angle",
          "must be in [0, 45 deg] (rad)");
  require(p.insertion >= Real(0.01) && p.insertion <= Real(0.3), "insertion",
          "must be in [0.01, 0.3] m");
  require(std::isfinite(p.roll), "roll", "must be finite");
  require(!p.shaft_direction || finite_nonzero(*p.shaft_direction), "shaft_direction",
          "must be finite and non-zero");
  require(finite_nonzero(p.reference_up), "reference_up", "must be finite and non-zero");
  require(p.vertical_fov > 0 && p.vertical_fov < degrees_to_radians(150), "vertical_fov",
          "must be in (0, 150 deg) (rad)");
  require(p.aspect > 0 && std::isfinite(p.aspect), "aspect", "must be finite and > 0");
  require(p.near_plane > 0 && std::isfinite(p.near_plane), "near_plane", "must be finite and > 0");
  require(p.far_plane > p.near_plane && std::isfinite(p.far_plane), "far_plane",
          "must be finite and beyond the near plane");
}

Mat4 perspective(Real vertical_fov, Real aspect, Real near_plane, Real far_plane) {
  const Real f = 1 / std::tan(vertical_fov / 2);
  Mat4 m = Mat4::Zero();
  m(0, 0) = f / aspect;
  m(1, 1) = f;
  // Maps camera z = -near to clip z/w = -1 and z = -far to +1.
  m(2, 2) = (far_plane + near_plane) / (near_plane - far_plane);
  m(2, 3) = 2 * far_plane * near_plane / (near_plane - far_plane);
  m(3, 2) = -1;  // w = distance in front of the eye
  return m;
}

EndoscopeView endoscope_view(const Vec3& port_position, const Vec3& port_direction,
                             const EndoscopeParams& params) {
  validate(params);
  require(port_position.allFinite(), "port position", "must be finite");
  require(finite_nonzero(port_direction), "port direction", "must be finite and non-zero");
  const Vec3 into = port_direction.normalized();
  const Vec3 shaft = params.shaft_direction ? Vec3(params.shaft_direction->normalized()) : into;
  // The scope pivots about the port but cannot leave the cavity through it.
  require(shaft.dot(into) > 0, "shaft_direction", "must point into the cavity");

  // Tilt side: the reference up across the shaft, rolled about the shaft.
  const Vec3 side = axis_angle(shaft, params.roll) * reference_across(shaft, params.reference_up);
  // Turning the pair (shaft, side) by the optics angle about shaft x side gives the view and
  // the image up, unit and perpendicular.
  const Real c = std::cos(params.optics_angle), s = std::sin(params.optics_angle);
  const Vec3 view_direction = (c * shaft + s * side).normalized();
  Vec3 up = c * side - s * shaft;
  up = (up - up.dot(view_direction) * view_direction).normalized();  // drop rounding along view

  EndoscopeView v;
  v.shaft = shaft;
  v.eye = port_position + params.insertion * shaft;
  v.view_direction = view_direction;
  v.up = up;
  // Camera axes in the world: x right, y up, z backwards (the view is -z).
  v.camera_to_world.rotation.col(0) = view_direction.cross(up);
  v.camera_to_world.rotation.col(1) = up;
  v.camera_to_world.rotation.col(2) = -view_direction;
  v.camera_to_world.translation = v.eye;

  const Mat3 world_to_camera = v.camera_to_world.rotation.transpose();
  v.view = Mat4::Identity();
  v.view.topLeftCorner<3, 3>() = world_to_camera;
  v.view.topRightCorner<3, 1>() = -(world_to_camera * v.eye);
  v.projection =
      perspective(params.vertical_fov, params.aspect, params.near_plane, params.far_plane);
  return v;
}

namespace {

Eigen::Matrix<Real, 4, 1> clip(const EndoscopeView& v, const Vec3& p) {
  return v.projection * (v.view * p.homogeneous());
}

// Between the near and far planes: -w <= z <= w with w > 0 (OpenGL clipping).
bool in_depth(const Eigen::Matrix<Real, 4, 1>& c) {
  return c.w() > 0 && c.z() >= -c.w() && c.z() <= c.w();
}

}  // namespace

std::optional<Vec2> project_to_ndc(const EndoscopeView& v, const Vec3& world_point) {
  const Eigen::Matrix<Real, 4, 1> c = clip(v, world_point);
  if (!in_depth(c)) return std::nullopt;
  return Vec2(c.x() / c.w(), c.y() / c.w());
}

bool in_view(const EndoscopeView& v, const Vec3& world_point) {
  const Eigen::Matrix<Real, 4, 1> c = clip(v, world_point);
  return in_depth(c) && std::abs(c.x()) <= c.w() && std::abs(c.y()) <= c.w();
}

}  // namespace imasim::surgery
