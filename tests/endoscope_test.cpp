// The endoscope at the camera port: the lens sits on the shaft through the port, angled optics
// tilt the view by exactly their angle towards the rolled up side, and the view and projection
// matrices follow the OpenGL conventions.
#include "surgery/endoscope.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace imasim::surgery {
namespace {

const Vec3 kPort(0.09, -0.02, 0.08);  // the default camera port's position (scene/ports.cpp)

// Angle between two vectors, accurate near 0 and pi.
Real angle_between(const Vec3& a, const Vec3& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

EndoscopeParams thirty_degree() {
  EndoscopeParams p;
  p.optics_angle = degrees_to_radians(30);
  return p;
}

// Random unit directions, fixed seed.
std::vector<Vec3> random_directions(int n) {
  std::mt19937_64 rng(20240611);
  std::uniform_real_distribution<Real> u(-1, 1);
  std::vector<Vec3> out;
  while (static_cast<int>(out.size()) < n) {
    const Vec3 d(u(rng), u(rng), u(rng));
    if (d.norm() > 0.2 && d.norm() <= 1) out.push_back(d.normalized());
  }
  return out;
}

Mat4 homogeneous(const Pose& pose) {
  Mat4 m = Mat4::Identity();
  m.topLeftCorner<3, 3>() = pose.rotation;
  m.topRightCorner<3, 1>() = pose.translation;
  return m;
}

TEST(Endoscope, ZeroDegreeOpticsLooksDownTheShaft) {
  const Vec3 direction = Vec3(-0.7, -0.5, 0.1).normalized();
  EndoscopeParams p;
  p.insertion = 0.07;
  const EndoscopeView v = endoscope_view(kPort, 3 * direction, p);  // need not be unit
  EXPECT_NEAR((v.eye - (kPort + 0.07 * direction)).norm(), 0, 1e-14);
  EXPECT_NEAR((v.view_direction - direction).norm(), 0, 1e-14);
  EXPECT_NEAR((v.camera_to_world.translation - v.eye).norm(), 0, 1e-14);

  // Pivoted about the port: the lens stays on the line through the port along the new shaft.
  const Vec3 pivoted = Vec3(-0.6, -0.7, -0.2).normalized();
  p.shaft_direction = 2 * pivoted;
  const EndoscopeView w = endoscope_view(kPort, direction, p);
  EXPECT_NEAR((w.eye - (kPort + 0.07 * pivoted)).norm(), 0, 1e-14);
  EXPECT_NEAR((w.view_direction - pivoted).norm(), 0, 1e-14);
  EXPECT_NEAR((w.shaft - pivoted).norm(), 0, 1e-14);
}

TEST(Endoscope, ThirtyDegreeOpticsTiltsTheViewByExactlyThirtyDegrees) {
  const Real thirty = degrees_to_radians(30);
  Real roll = -2;
  for (const Vec3& d : random_directions(200)) {
    EndoscopeParams p = thirty_degree();
    p.roll = roll;
    roll += 0.37;
    const EndoscopeView v = endoscope_view(kPort, d, p);
    ASSERT_NEAR(angle_between(v.view_direction, d), thirty, 1e-12);
    ASSERT_NEAR(v.view_direction.norm(), 1, 1e-15);
    ASSERT_NEAR(v.up.norm(), 1, 1e-15);
    ASSERT_NEAR(v.up.dot(v.view_direction), 0, 1e-15);
    // The tilt is towards the image up side: the shaft appears below the image centre, in the
    // plane of view and up (no sideways component).
    const Vec3 shaft_in_camera = v.camera_to_world.rotation.transpose() * d;
    ASSERT_LT(shaft_in_camera.y(), -0.49);
    ASSERT_NEAR(shaft_in_camera.x(), 0, 1e-15);
  }
  // At roll 0 the tilt goes towards the reference up (cranial, -z, by default).
  const Vec3 d = Vec3(-0.8, -0.6, 0).normalized();
  const EndoscopeView v = endoscope_view(kPort, d, thirty_degree());
  EXPECT_NEAR((v.view_direction - (std::cos(thirty) * d - std::sin(thirty) * Vec3::UnitZ())).norm(),
              0, 1e-15);
}

TEST(Endoscope, RollFollowsTheRightHandRuleAboutTheShaft) {
  // Shaft -y, up at roll 0 is -z; a quarter turn about -y takes -z to (-y) x (-z) = +x.
  EndoscopeParams p = thirty_degree();
  p.roll = degrees_to_radians(90);
  const EndoscopeView v = endoscope_view(kPort, -Vec3::UnitY(), p);
  const Real thirty = degrees_to_radians(30);
  EXPECT_NEAR((v.view_direction - Vec3(std::sin(thirty), -std::cos(thirty), 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((v.up - Vec3(std::cos(thirty), std::sin(thirty), 0)).norm(), 0, 1e-15);
}

TEST(Endoscope, RollByPiMirrorsTheTiltAndTwoPiReturns) {
  for (const Vec3& d : random_directions(50)) {
    EndoscopeParams p = thirty_degree();
    p.roll = 0.3;
    const EndoscopeView v0 = endoscope_view(kPort, d, p);
    p.roll = 0.3 + kPi;
    const EndoscopeView half = endoscope_view(kPort, d, p);
    p.roll = 0.3 + 2 * kPi;
    const EndoscopeView full = endoscope_view(kPort, d, p);
    // Mirrored about the shaft: same component along it, opposite component across it.
    const Vec3 mirrored = 2 * v0.view_direction.dot(d) * d - v0.view_direction;
    ASSERT_NEAR((half.view_direction - mirrored).norm(), 0, 1e-14);
    ASSERT_GT((half.view_direction - v0.view_direction).norm(), 0.99);  // 2 sin 30 deg = 1
    ASSERT_NEAR((full.view_direction - v0.view_direction).norm(), 0, 1e-14);
    ASSERT_NEAR((full.camera_to_world.rotation - v0.camera_to_world.rotation).norm(), 0, 1e-14);
    for (const EndoscopeView* v : {&v0, &half, &full}) {
      const Mat3& r = v->camera_to_world.rotation;
      ASSERT_NEAR((r.transpose() * r - Mat3::Identity()).norm(), 0, 1e-14);
      ASSERT_NEAR(r.determinant(), 1, 1e-14);
    }
  }
}

TEST(Endoscope, ViewMatrixInvertsTheCameraPoseAndDepthFollowsOpenGl) {
  EndoscopeParams p = thirty_degree();
  p.roll = 1.1;
  p.near_plane = 0.004;
  p.far_plane = 0.25;
  const EndoscopeView v = endoscope_view(kPort, Vec3(-0.7, -0.6, 0.2), p);
  EXPECT_NEAR((v.view * homogeneous(v.camera_to_world) - Mat4::Identity()).norm(), 0, 1e-13);
  EXPECT_NEAR((v.view * v.eye.homogeneous() - Vec3::Zero().homogeneous()).norm(), 0, 1e-15);

  const Real n = p.near_plane, f = p.far_plane;
  // Just inside the near and far planes: exactly on them rounding decides.
  for (Real d : {0.004 * (1 + 1e-9), 0.01, 0.05, 0.12, 0.25 * (1 - 1e-9)}) {
    const Vec3 point = v.eye + d * v.view_direction;
    const std::optional<Vec2> ndc = project_to_ndc(v, point);
    ASSERT_TRUE(ndc.has_value()) << d;
    EXPECT_NEAR(ndc->norm(), 0, 1e-12);
    const Eigen::Matrix<Real, 4, 1> clip = v.projection * (v.view * point.homogeneous());
    // OpenGL: z_ndc = (f + n) / (f - n) - 2 f n / ((f - n) d); -1 at the near, +1 at the far.
    EXPECT_NEAR(clip.z() / clip.w(), (f + n) / (f - n) - 2 * f * n / ((f - n) * d), 1e-12);
    EXPECT_NEAR(clip.w(), d, 1e-15);
  }
  EXPECT_FALSE(project_to_ndc(v, v.eye + 0.003 * v.view_direction).has_value());  // too near
  EXPECT_FALSE(project_to_ndc(v, v.eye + 0.26 * v.view_direction).has_value());   // too far
}

TEST(Endoscope, FieldOfViewEdgesMapToNdcOne) {
  EndoscopeParams p = thirty_degree();
  p.roll = -0.4;
  const EndoscopeView v = endoscope_view(kPort, Vec3(-0.8, -0.5, -0.1), p);
  const Vec3 right = v.view_direction.cross(v.up);
  const Real half_height = std::tan(p.vertical_fov / 2);
  const Real half_width = p.aspect * half_height;
  for (Real d : {0.01, 0.08, 0.2}) {
    const Vec3 centre = v.eye + d * v.view_direction;
    const std::optional<Vec2> top = project_to_ndc(v, centre + d * half_height * v.up);
    ASSERT_TRUE(top.has_value());
    EXPECT_NEAR(top->y(), 1, 1e-12);
    EXPECT_NEAR(top->x(), 0, 1e-12);
    const std::optional<Vec2> side = project_to_ndc(v, centre + d * half_width * right);
    ASSERT_TRUE(side.has_value());
    EXPECT_NEAR(side->x(), 1, 1e-12);
    EXPECT_NEAR(side->y(), 0, 1e-12);
    // Just inside the corner is in view; just beyond either edge is not.
    EXPECT_TRUE(in_view(v, centre + 0.999 * d * (half_height * v.up + half_width * right)));
    EXPECT_FALSE(in_view(v, centre + 1.001 * d * half_height * v.up));
    EXPECT_FALSE(in_view(v, centre - 1.001 * d * half_width * right));
    EXPECT_TRUE(in_view(v, centre));
  }
  // Behind the eye: neither projected nor in view, even straight back along the axis.
  for (Real d : {0.0, 0.01, 0.1}) {
    const Vec3 behind = v.eye - d * v.view_direction;
    EXPECT_FALSE(project_to_ndc(v, behind).has_value()) << d;
    EXPECT_FALSE(in_view(v, behind)) << d;
  }
  EXPECT_FALSE(in_view(v, v.eye + 0.31 * v.view_direction));  // beyond the far plane
}

TEST(Endoscope, ImageUpProjectsUpwards) {
  for (Real optics : {0.0, 30.0}) {
    EndoscopeParams p;
    p.optics_angle = degrees_to_radians(optics);
    p.roll = 2.5;
    const EndoscopeView v = endoscope_view(kPort, Vec3(-0.7, -0.6, 0.1), p);
    const Vec3 on_axis = v.eye + 0.06 * v.view_direction;
    EXPECT_GT(project_to_ndc(v, on_axis + 0.01 * v.up)->y(), 0.1);
    EXPECT_LT(project_to_ndc(v, on_axis - 0.01 * v.up)->y(), -0.1);
    EXPECT_NEAR(project_to_ndc(v, on_axis + 0.01 * v.up)->x(), 0, 1e-12);
  }
  // 0 deg optics at roll 0: the image up is the reference up made perpendicular to the shaft.
  const Vec3 d = Vec3(-0.7, -0.6, 0.3).normalized();
  const EndoscopeView v = endoscope_view(kPort, d, EndoscopeParams{});
  const Vec3 cranial = -Vec3::UnitZ();
  EXPECT_NEAR((v.up - (cranial - cranial.dot(d) * d).normalized()).norm(), 0, 1e-15);
}

TEST(Endoscope, ReferenceUpAlongTheShaftFallsBackToAnotherAxis) {
  for (const Vec3& d : {Vec3(-Vec3::UnitZ()), Vec3(Vec3::UnitZ()), Vec3(0, 1e-9, -1)}) {
    EndoscopeParams p = thirty_degree();
    const EndoscopeView v = endoscope_view(kPort, d, p);
    ASSERT_TRUE(v.up.allFinite());
    EXPECT_NEAR(v.up.norm(), 1, 1e-15);
    EXPECT_NEAR(angle_between(v.view_direction, d.normalized()), degrees_to_radians(30), 1e-12);
    // Here x is the axis least aligned with the shaft (first on ties): the tilt goes along x.
    EXPECT_NEAR(v.view_direction.x(), std::sin(degrees_to_radians(30)), 1e-12);
  }
}

TEST(Endoscope, ShaftMustPointIntoTheCavity) {
  EndoscopeParams p;
  p.shaft_direction = Vec3(0.1, 1, 0);  // out through the port
  EXPECT_THROW(endoscope_view(kPort, -Vec3::UnitY(), p), std::invalid_argument);
  EXPECT_THROW(endoscope_view(kPort, Vec3::Zero(), EndoscopeParams{}), std::invalid_argument);
  EXPECT_THROW(endoscope_view(Vec3(std::numeric_limits<Real>::quiet_NaN(), 0, 0), -Vec3::UnitY(),
                              EndoscopeParams{}),
               std::invalid_argument);
}

TEST(Endoscope, ValidateNamesTheBadField) {
  EXPECT_NO_THROW(validate(EndoscopeParams{}));
  EXPECT_NO_THROW(validate(thirty_degree()));
  const Real nan = std::numeric_limits<Real>::quiet_NaN();
  const Real inf = std::numeric_limits<Real>::infinity();
  struct Case {
    std::string field;
    std::function<void(EndoscopeParams&)> spoil;
  };
  const std::vector<Case> cases = {
      {"optics_angle", [](EndoscopeParams& p) { p.optics_angle = -0.01; }},
      {"optics_angle", [](EndoscopeParams& p) { p.optics_angle = degrees_to_radians(46); }},
      {"optics_angle", [&](EndoscopeParams& p) { p.optics_angle = nan; }},
      {"insertion", [](EndoscopeParams& p) { p.insertion = 0.009; }},
      {"insertion", [](EndoscopeParams& p) { p.insertion = 0.31; }},
      {"insertion", [&](EndoscopeParams& p) { p.insertion = nan; }},
      {"roll", [&](EndoscopeParams& p) { p.roll = nan; }},
      {"roll", [&](EndoscopeParams& p) { p.roll = inf; }},
      {"shaft_direction", [](EndoscopeParams& p) { p.shaft_direction = Vec3::Zero(); }},
      {"shaft_direction", [&](EndoscopeParams& p) { p.shaft_direction = Vec3(nan, 0, -1); }},
      {"reference_up", [](EndoscopeParams& p) { p.reference_up = Vec3::Zero(); }},
      {"reference_up", [&](EndoscopeParams& p) { p.reference_up = Vec3(0, inf, 0); }},
      {"vertical_fov", [](EndoscopeParams& p) { p.vertical_fov = 0; }},
      {"vertical_fov", [](EndoscopeParams& p) { p.vertical_fov = degrees_to_radians(150); }},
      {"vertical_fov", [&](EndoscopeParams& p) { p.vertical_fov = nan; }},
      {"aspect", [](EndoscopeParams& p) { p.aspect = 0; }},
      {"aspect", [&](EndoscopeParams& p) { p.aspect = nan; }},
      {"aspect", [&](EndoscopeParams& p) { p.aspect = inf; }},
      {"near_plane", [](EndoscopeParams& p) { p.near_plane = 0; }},
      {"near_plane", [&](EndoscopeParams& p) { p.near_plane = nan; }},
      {"far_plane", [](EndoscopeParams& p) { p.far_plane = p.near_plane; }},
      {"far_plane", [&](EndoscopeParams& p) { p.far_plane = nan; }},
      {"far_plane", [&](EndoscopeParams& p) { p.far_plane = inf; }},
  };
  for (const Case& c : cases) {
    EndoscopeParams p = thirty_degree();
    c.spoil(p);
    try {
      validate(p);
      ADD_FAILURE() << "no throw for a bad " << c.field;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(c.field), std::string::npos)
          << c.field << " not in: " << e.what();
    }
    // endoscope_view validates too.
    EXPECT_THROW(endoscope_view(kPort, -Vec3::UnitY(), p), std::invalid_argument) << c.field;
  }
}

}  // namespace
}  // namespace imasim::surgery
