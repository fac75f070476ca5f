// Instrument-tissue contact (SPEC S4): the shapes' signed distances against closed forms and
// finite differences, the XPBD contact projection (hard and compliant), positional Coulomb
// friction, the instrument's geometry, and the summary's counts and determinism.
#include "surgery/tool_contact.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace imasim::surgery {
namespace {

// x = point + distance * normal, with a unit normal.
void ExpectConsistent(const SurfacePoint& s, const Vec3& x) {
  EXPECT_NEAR(s.normal.norm(), 1, 1e-15);
  EXPECT_NEAR((s.point + s.distance * s.normal - x).norm(), 0, 1e-15);
}

void ExpectSurface(const SurfacePoint& s, Real distance, const Vec3& point, const Vec3& normal) {
  EXPECT_NEAR(s.distance, distance, 1e-15);
  EXPECT_NEAR((s.point - point).norm(), 0, 1e-15);
  EXPECT_NEAR((s.normal - normal).norm(), 0, 1e-15);
}

TEST(ToolContact, CapsuleSurfaceMatchesClosedForms) {
  const Capsule c{Vec3(0, 0, 0), Vec3(0, 0, 2), Real(0.5)};
  {  // inside the cylinder: out radially
    const Vec3 x(0.2, 0, 1);
    const SurfacePoint s = capsule_surface(c, x);
    ExpectSurface(s, -0.3, Vec3(0.5, 0, 1), Vec3::UnitX());
    ExpectConsistent(s, x);
  }
  {  // outside the cylinder
    const Vec3 x(0, 3, 1);
    const SurfacePoint s = capsule_surface(c, x);
    ExpectSurface(s, 2.5, Vec3(0, 0.5, 1), Vec3::UnitY());
    ExpectConsistent(s, x);
  }
  {  // on the axis beyond either cap: along the axis
    const SurfacePoint top = capsule_surface(c, Vec3(0, 0, 3));
    ExpectSurface(top, 0.5, Vec3(0, 0, 2.5), Vec3::UnitZ());
    const SurfacePoint bottom = capsule_surface(c, Vec3(0, 0, -1));
    ExpectSurface(bottom, 0.5, Vec3(0, 0, -0.5), -Vec3::UnitZ());
  }
  {  // off the axis beyond a cap: from the cap's centre (0.6, 0.8 is a unit direction)
    const Vec3 x(0, 0.6, 2.8);
    const SurfacePoint s = capsule_surface(c, x);
    ExpectSurface(s, 0.5, Vec3(0, 0.3, 2.4), Vec3(0, 0.6, 0.8));
    ExpectConsistent(s, x);
  }
  {                                // inside the cap
    const Vec3 x(0, -0.12, 2.16);  // 0.2 from b along (0, -0.6, 0.8)
    const SurfacePoint s = capsule_surface(c, x);
    ExpectSurface(s, -0.3, Vec3(0, -0.3, 2.4), Vec3(0, -0.6, 0.8));
  }
  {  // on the axis, inside: any direction perpendicular to the axis, the full radius deep
    const Vec3 x(0, 0, 1.2);
    const SurfacePoint s = capsule_surface(c, x);
    EXPECT_NEAR(s.distance, -0.5, 1e-15);
    EXPECT_NEAR(s.normal.norm(), 1, 1e-15);
    EXPECT_NEAR(s.normal.z(), 0, 1e-15);
    ExpectConsistent(s, x);
  }
  {  // on the axis of a tilted capsule: still perpendicular to its axis
    const Capsule tilted{Vec3(1, 0, 0), Vec3(2, 1, 1), Real(0.5)};
    const Vec3 x(1.5, 0.5, 0.5);
    const SurfacePoint s = capsule_surface(tilted, x);
    EXPECT_NEAR(s.distance, -0.5, 1e-15);
    EXPECT_NEAR(s.normal.dot(tilted.b - tilted.a), 0, 1e-15);
    ExpectConsistent(s, x);
  }
  {  // a degenerate capsule is a sphere
    const Capsule sphere{Vec3(1, 1, 1), Vec3(1, 1, 1), 1};
    const SurfacePoint s = capsule_surface(sphere, Vec3(1, 3, 1));
    ExpectSurface(s, 1, Vec3(1, 2, 1), Vec3::UnitY());
  }
}

TEST(ToolContact, BoxSurfaceMatchesClosedForms) {
  OrientedBox box;
  box.pose.rotation = axis_angle(Vec3(1, 2, 3), Real(0.7));
  box.pose.translation = Vec3(1, 2, 3);
  box.half_extents = Vec3(0.1, 0.2, 0.3);
  const Mat3& R = box.pose.rotation;
  // Each case in the box's frame: query, expected distance, closest point, normal.
  struct Case {
    Vec3 q;
    Real distance;
    Vec3 point, normal;
  };
  const Real edge = std::sqrt(Real(0.05));    // |(0.1, 0.2, 0)|
  const Real corner = std::sqrt(Real(0.41));  // |(-0.3, 0.4, -0.4)|
  const Case cases[] = {
      // Inside: the nearest face.
      {Vec3(0.05, 0, 0), -0.05, Vec3(0.1, 0, 0), Vec3::UnitX()},
      {Vec3(0, -0.15, 0.01), -0.05, Vec3(0, -0.2, 0.01), -Vec3::UnitY()},
      {Vec3(0.02, 0.05, -0.25), -0.05, Vec3(0.02, 0.05, -0.3), -Vec3::UnitZ()},
      {Vec3(0, 0, 0), -0.1, Vec3(0.1, 0, 0), Vec3::UnitX()},  // centre: the nearest face
      // Outside a face, an edge, a corner.
      {Vec3(0.03, -0.1, 0.5), 0.2, Vec3(0.03, -0.1, 0.3), Vec3::UnitZ()},
      {Vec3(0.2, 0.4, 0), edge, Vec3(0.1, 0.2, 0), Vec3(0.1, 0.2, 0) / edge},
      {Vec3(-0.4, 0.6, -0.7), corner, Vec3(-0.1, 0.2, -0.3), Vec3(-0.3, 0.4, -0.4) / corner},
      // On a face.
      {Vec3(0.1, 0.05, 0.1), 0, Vec3(0.1, 0.05, 0.1), Vec3::UnitX()},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(::testing::Message() << "q = " << c.q.transpose());
    const Vec3 x = box.pose.apply(c.q);
    const SurfacePoint s = box_surface(box, x);
    EXPECT_NEAR(s.distance, c.distance, 1e-15);
    EXPECT_NEAR((s.point - box.pose.apply(c.point)).norm(), 0, 1e-15);
    EXPECT_NEAR((s.normal - R * c.normal).norm(), 0, 1e-15);
    ExpectConsistent(s, x);
  }
}

// Central differences of the signed distance equal the normal wherever it is smooth.
TEST(ToolContact, NormalIsTheGradientOfTheSignedDistance) {
  const Capsule capsule{Vec3(0.1, -0.2, 0.3), Vec3(0.5, 0.4, -0.1), Real(0.15)};
  OrientedBox box;
  box.pose.rotation = axis_angle(Vec3(-1, 0.5, 2), Real(1.1));
  box.pose.translation = Vec3(0.2, 0.1, -0.3);
  box.half_extents = Vec3(0.1, 0.25, 0.15);
  std::mt19937_64 rng(20240601);
  std::uniform_real_distribution<Real> u(-0.6, 0.6);
  const Real h = 1e-6;
  int capsule_checked = 0, box_checked = 0, box_inside = 0;
  for (int n = 0; n < 2000; ++n) {
    const Vec3 x(u(rng) + 0.3, u(rng) + 0.1, u(rng));
    const SurfacePoint sc = capsule_surface(capsule, x);
    if (sc.distance + capsule.radius > 0.05) {  // away from the axis (the medial axis)
      Vec3 gradient;
      for (int i = 0; i < 3; ++i) {
        const Vec3 e = h * Vec3::Unit(i);
        gradient[i] =
            (capsule_surface(capsule, x + e).distance - capsule_surface(capsule, x - e).distance) /
            (2 * h);
      }
      EXPECT_NEAR((gradient - sc.normal).norm(), 0, 1e-6) << x.transpose();
      ++capsule_checked;
    }
    const Vec3 y = box.pose.translation + Real(0.4) * Vec3(u(rng), u(rng), u(rng));
    const SurfacePoint sb = box_surface(box, y);
    if (std::abs(sb.distance) < 0.02) continue;  // the edges' curvature
    if (sb.distance < 0) {
      // Away from the medial planes, where the nearest face changes: the two nearest faces
      // differ in distance.
      const Vec3 q = box.pose.rotation.transpose() * (y - box.pose.translation);
      Vec3 to_face = box.half_extents - q.cwiseAbs();
      std::sort(to_face.data(), to_face.data() + 3);
      if (to_face[1] - to_face[0] < 0.02) continue;
      ++box_inside;
    }
    Vec3 gradient;
    for (int i = 0; i < 3; ++i) {
      const Vec3 e = h * Vec3::Unit(i);
      gradient[i] = (box_surface(box, y + e).distance - box_surface(box, y - e).distance) / (2 * h);
    }
    EXPECT_NEAR((gradient - sb.normal).norm(), 0, 1e-6) << y.transpose();
    ++box_checked;
  }
  EXPECT_GT(capsule_checked, 1000);
  EXPECT_GT(box_checked, 1000);
  EXPECT_GT(box_inside, 20);
}

// One capsule along z, r = 4 mm: the shaft.
ToolGeometry Shaft(Real slide = 0) {
  ToolGeometry tool;
  tool.capsules.push_back({Vec3(0, 0, slide), Vec3(0, 0, Real(0.1) + slide), Real(0.004)});
  return tool;
}

TEST(ToolContact, ParticleInsideTheShaftEndsOnItsSurfacePlusMargin) {
  const ToolGeometry tool = Shaft();
  const ContactParams params;
  const Real dt = 0.01, surface = Real(0.004) + params.margin;
  physics::Particles P;
  const Vec3 inside(0.001, 0.002, 0.05);
  P.add(inside, 0.001, 0);
  P.add(inside, 0.001, 0);
  P.fix(1);                                // fixed: left to whoever drives it
  P.add(Vec3(0.0041, 0, 0.06), 0.001, 0);  // outside, but within the margin
  P.add(Vec3(0.01, 0, 0.05), 0.001, 0);    // outside, inside the bounding box
  P.add(Vec3(0.3, -0.2, 0.5), 0.001, 0);   // far away
  for (std::size_t i = 0; i < P.size(); ++i)
    P.velocity[i] = Vec3(0.1, -0.2, 0.3) * Real(i + 1);
  // The tool pressed into resting tissue (start = now): pushed out radially.
  const std::vector<Vec3> start = P.position;
  const physics::Particles before = P;
  std::vector<ToolContact> contacts;
  contacts.reserve(8);
  const ContactSummary summary = resolve_tool_contacts(P, start, tool, params, dt, contacts);

  const Vec3 radial = Vec3(1, 2, 0).normalized();
  const Vec3 expected = Vec3(0, 0, 0.05) + surface * radial;
  EXPECT_NEAR((P.position[0] - expected).norm(), 0, 1e-12);
  EXPECT_NEAR(P.position[0].head<2>().norm(), surface, 1e-12);
  EXPECT_NEAR((P.velocity[0] - (P.position[0] - start[0]) / dt).norm(), 0, 1e-12);
  EXPECT_NEAR((P.velocity[0] - (surface - std::sqrt(Real(5e-6))) * radial / dt).norm(), 0, 1e-9);
  EXPECT_EQ(P.position[1], before.position[1]);
  EXPECT_EQ(P.velocity[1], before.velocity[1]);
  EXPECT_NEAR((P.position[2] - Vec3(surface, 0, 0.06)).norm(), 0, 1e-12);
  for (std::size_t i = 3; i < 5; ++i) {  // bit for bit
    EXPECT_EQ(P.position[i], before.position[i]);
    EXPECT_EQ(P.velocity[i], before.velocity[i]);
  }
  ASSERT_EQ(summary.count, 2u);
  ASSERT_EQ(contacts.size(), 2u);
  EXPECT_EQ(contacts[0].particle, 0u);
  EXPECT_NEAR(contacts[0].depth, surface - std::sqrt(Real(5e-6)), 1e-15);
  EXPECT_NEAR((contacts[0].normal - radial).norm(), 0, 1e-15);
  EXPECT_NEAR((contacts[0].point - (Vec3(0, 0, 0.05) + Real(0.004) * radial)).norm(), 0, 1e-15);
  EXPECT_EQ(contacts[1].particle, 2u);
  EXPECT_NEAR(contacts[1].depth, surface - 0.0041, 1e-15);
}

// The broad phase's box is grown by the margin: particles within the margin beyond each of its
// six faces are still found.
TEST(ToolContact, BroadPhaseKeepsTheMargin) {
  const ContactParams params;
  const Real r = Real(0.004), beyond = r + params.margin / 2;
  physics::Particles P;
  for (const Vec3& x : {Vec3(beyond, 0, 0.05), Vec3(-beyond, 0, 0.05), Vec3(0, beyond, 0.05),
                        Vec3(0, -beyond, 0.05), Vec3(0, 0, -beyond), Vec3(0, 0, 0.1 + beyond)})
    P.add(x, 0.001, 0);
  const std::vector<Vec3> start = P.position;
  std::vector<ToolContact> contacts;
  const ContactSummary s = resolve_tool_contacts(P, start, Shaft(), params, 0.01, contacts);
  EXPECT_EQ(s.count, 6u);
  EXPECT_EQ(s.inside, 0u);  // in the margin band only: not a missed contact
  EXPECT_NEAR(s.max_depth, params.margin / 2, 1e-15);
  // A turned box's bounding box covers its turned extent: a point inside near its tip.
  ToolGeometry turned;
  OrientedBox box;
  box.pose.rotation = axis_angle(Vec3::UnitZ(), kPi / 4);
  box.half_extents = Vec3(0.01, 0.001, 0.001);
  turned.boxes.push_back(box);
  physics::Particles Q;
  Q.add(box.pose.apply(Vec3(0.009, 0.0005, 0)), 0.001, 0);
  const std::vector<Vec3> start_q = Q.position;
  const ContactSummary q = resolve_tool_contacts(Q, start_q, turned, params, 0.01, contacts);
  EXPECT_EQ(q.count, 1u);
  EXPECT_EQ(q.inside, 1u);  // inside the box itself
  EXPECT_NEAR((Q.position[0] - box.pose.apply(Vec3(0.009, 0.001 + params.margin, 0))).norm(), 0,
              1e-15);
}

TEST(ToolContact, CompliantContactProjectsTheClosedFormFraction) {
  const ToolGeometry tool = Shaft();
  ContactParams params;
  params.compliance = 1e-6;
  const Real dt = 0.01;
  const Real alpha_tilde = params.compliance / (dt * dt);  // 0.01 (unit: 1/kg)
  for (const Real mass : {Real(0.001), Real(50), Real(200)}) {
    physics::Particles P;
    P.add(Vec3(0.003, 0, 0.05), mass, 0);
    const std::vector<Vec3> start = P.position;
    std::vector<ToolContact> contacts;
    resolve_tool_contacts(P, start, tool, params, dt, contacts);
    const Real w = 1 / mass, d = Real(0.004) + params.margin - Real(0.003);
    EXPECT_NEAR(P.position[0].x() - 0.003, d * w / (w + alpha_tilde), 1e-12) << mass;
    EXPECT_NEAR(P.position[0].y(), 0, 1e-15);
    EXPECT_NEAR(P.position[0].z(), 0.05, 1e-15);
  }
}

// A particle resting on the shaft (start = now, 0.4 mm deep with the margin) while the shaft
// slides along its axis by `slide` this step: returns the particle's final position.
Vec3 SlideUnder(Real slide, const ContactParams& params, Real dt, Vec3* velocity = nullptr) {
  ToolGeometry tool = Shaft(slide);
  tool.velocity = Vec3(0, 0, slide / dt);
  physics::Particles P;
  P.add(Vec3(0.0038, 0, 0.05), 0.001, 0);
  const std::vector<Vec3> start = P.position;
  std::vector<ToolContact> contacts;
  resolve_tool_contacts(P, start, tool, params, dt, contacts);
  EXPECT_EQ(contacts.size(), 1u);
  EXPECT_NEAR(P.position[0].x(), 0.004 + params.margin, 1e-12);
  if (velocity) *velocity = P.velocity[0];
  return P.position[0];
}

TEST(ToolContact, StaticFrictionCarriesTheParticleWithTheTool) {
  const ContactParams params;
  const Real dt = 0.01, d = Real(0.0004);
  for (const Real fraction : {Real(0.1), Real(0.5), Real(0.99)}) {
    const Real slide = fraction * params.static_friction * d;
    Vec3 v;
    const Vec3 x = SlideUnder(slide, params, dt, &v);
    EXPECT_NEAR(x.z() - 0.05 - slide, 0, 1e-15) << fraction;  // no relative tangential motion
    EXPECT_NEAR(x.y(), 0, 1e-15);
    EXPECT_NEAR(v.z(), slide / dt, 1e-12);  // moves with the tool
    EXPECT_NEAR(v.x(), d / dt, 1e-12);
  }
}

TEST(ToolContact, KineticFrictionReducesTheSlipByMuKTimesTheDepth) {
  const ContactParams params;
  const Real dt = 0.01, d = Real(0.0004);
  for (const Real fraction : {Real(1.01), Real(2), Real(10)}) {
    const Real slide = fraction * params.static_friction * d;
    const Vec3 x = SlideUnder(slide, params, dt);
    // Dragged mu_k d along: the slip relative to the tool falls from `slide` by mu_k d.
    EXPECT_NEAR(x.z() - 0.05, params.kinetic_friction * d, 1e-15) << fraction;
    EXPECT_NEAR(slide - (x.z() - 0.05), slide - params.kinetic_friction * d, 1e-15);
  }
  // Slip from the particle's own motion, the tool still: reduced the same way, against it.
  physics::Particles P;
  P.add(Vec3(0.0038, 0, 0.051), 0.001, 0);
  const std::vector<Vec3> start{Vec3(0.0038, 0, 0.05)};
  std::vector<ToolContact> contacts;
  resolve_tool_contacts(P, start, Shaft(), params, dt, contacts);
  EXPECT_NEAR(P.position[0].z() - 0.05, 0.001 - params.kinetic_friction * d, 1e-15);
  EXPECT_NEAR((P.velocity[0] - (P.position[0] - start[0]) / dt).norm(), 0, 1e-12);
}

TEST(ToolContact, WithoutFrictionTheTangentialMotionIsUnchanged) {
  ContactParams params;
  params.static_friction = params.kinetic_friction = 0;
  const Real dt = 0.01;
  EXPECT_EQ(SlideUnder(0.0001, params, dt).z(), Real(0.05));
  EXPECT_EQ(SlideUnder(0.01, params, dt).z(), Real(0.05));
  // The particle's own tangential motion is kept too.
  physics::Particles P;
  P.add(Vec3(0.0038, 0.0001, 0.05), 0.001, 0);
  const std::vector<Vec3> start{Vec3(0.0035, 0.0004, 0.0495)};
  std::vector<ToolContact> contacts;
  resolve_tool_contacts(P, start, Shaft(), params, dt, contacts);
  ASSERT_EQ(contacts.size(), 1u);
  EXPECT_EQ(P.position[0].z(), Real(0.05));
  const Vec3 radial = Vec3(0.0038, 0.0001, 0).normalized();
  EXPECT_NEAR((P.position[0].head<2>() - (0.004 + params.margin) * radial.head<2>()).norm(), 0,
              1e-12);
}

TEST(ToolContact, GeometryFollowsTheInstrument) {
  const InstrumentParams params;
  InstrumentState state;
  state.controller.rotation = axis_angle(Vec3(0.3, 1, -0.2), Real(0.8));
  state.controller.translation = Vec3(0.01, -0.02, 0.07);
  state.local.rotation = axis_angle(Vec3(1, 0, 0.4), Real(-0.3));
  ToolGeometry tool;
  tool.velocity = Vec3(1, 2, 3);
  for (const Real degrees : {Real(0), Real(12), Real(30)}) {
    SCOPED_TRACE(degrees);
    state.jaw_angle = degrees_to_radians(degrees);
    make_tool_geometry(params, state, tool);
    const Pose W = world_pose(params, state);
    const Vec3 hinge = W.translation, l = W.rotation.col(0), n = W.rotation.col(1),
               f = W.rotation.col(2);
    EXPECT_EQ(tool.velocity, Vec3::Zero());
    ASSERT_EQ(tool.capsules.size(), 1u);
    ASSERT_EQ(tool.boxes.size(), 2u);
    // The shaft ends at the hinge and lies along -f.
    const Capsule& shaft = tool.capsules[0];
    EXPECT_NEAR((shaft.b - hinge).norm(), 0, 1e-15);
    EXPECT_NEAR((shaft.a - (hinge - params.shaft_length * f)).norm(), 0, 1e-15);
    EXPECT_EQ(shaft.radius, params.shaft_radius);
    // Jaws: turned by +-theta about the hinge axis -l, so the jaw's f is cos(theta) f +-
    // sin(theta) n (R(theta, -x) takes (0, 0, 1) to (0, sin, cos)): the upper jaw opens towards
    // +n, the lower towards -n; each box centred half-way along it.
    const Real c = std::cos(state.jaw_angle), s = std::sin(state.jaw_angle);
    const Real half_length = params.jaws.length / 2;
    const Vec3 jaw_f[2] = {c * f + s * n, c * f - s * n};
    const Pose jaw[2] = {upper_jaw_pose(params, state), lower_jaw_pose(params, state)};
    for (int k = 0; k < 2; ++k) {
      const OrientedBox& box = tool.boxes[static_cast<std::size_t>(k)];
      EXPECT_NEAR((box.pose.translation - (hinge + half_length * jaw_f[k])).norm(), 0, 1e-15);
      EXPECT_NEAR((box.pose.rotation.col(2) - jaw_f[k]).norm(), 0, 1e-15);
      EXPECT_NEAR((box.pose.rotation.col(0) - l).norm(), 0, 1e-15);
      EXPECT_NEAR((box.pose.rotation - jaw[k].rotation).norm(), 0, 1e-15);
      EXPECT_EQ(box.half_extents,
                Vec3(params.jaws.width / 2, kJawThickness / 2, params.jaws.length / 2));
      // The hinge and the jaw's tip lie on the box's end faces.
      EXPECT_NEAR(box_surface(box, hinge).distance, 0, 1e-15);
      EXPECT_NEAR(box_surface(box, jaw_tip(params, jaw[k])).distance, 0, 1e-15);
    }
  }
  // Rebuilt with the capacity in place: same storage.
  const Capsule* capsules = tool.capsules.data();
  const OrientedBox* boxes = tool.boxes.data();
  state.jaw_angle = 0.1;
  make_tool_geometry(params, state, tool);
  EXPECT_EQ(tool.capsules.data(), capsules);
  EXPECT_EQ(tool.boxes.data(), boxes);
}

TEST(ToolContact, SummaryCountsPerObjectAndReportsTheDeepest) {
  // A capsule along x (r = 1 cm) and a box around its end.
  ToolGeometry tool;
  tool.capsules.push_back({Vec3(0, 0, 0), Vec3(0.1, 0, 0), Real(0.01)});
  OrientedBox box;
  box.pose.translation = Vec3(0.1, 0, 0);
  box.half_extents = Vec3(0.03, 0.02, 0.02);
  tool.boxes.push_back(box);
  const ContactParams params;
  const Real m = params.margin;
  physics::Particles P;
  P.add(Vec3(0.03, 0.008, 0), 0.001, 0);    // capsule, depth 2 mm + m
  P.add(Vec3(0.122, 0, 0), 0.001, 2);       // box only, 8 mm + m: the deepest
  P.add(Vec3(0.05, 0, 0.0095), 0.001, 9);   // capsule, 0.5 mm + m; object 9 -> slot 7
  P.add(Vec3(0.075, 0, 0.009), 0.001, 12);  // capsule, 1 mm + m, out to z = 1 cm + m, still
                                            // in the box: 5 mm + m from its x- face
  P.add(Vec3(0.05, 0.05, 0), 0.001, 0);     // outside
  P.add(Vec3(0.05, 0, 0), 0.001, 1);        // inside but fixed
  P.fix(5);
  const std::vector<Vec3> start = P.position;
  const physics::Particles initial = P;

  std::vector<ToolContact> contacts;
  contacts.reserve(16);
  const ToolContact* storage = contacts.data();
  const ContactSummary s = resolve_tool_contacts(P, start, tool, params, 0.01, contacts);
  EXPECT_EQ(contacts.data(), storage);  // no allocation while it fits
  EXPECT_EQ(s.count, 5u);
  const std::uint32_t per_object[8] = {1, 0, 1, 0, 0, 0, 0, 3};
  for (int k = 0; k < 8; ++k)
    EXPECT_EQ(s.per_object[k], per_object[k]) << k;
  EXPECT_NEAR(s.max_depth, 0.008 + m, 1e-15);
  EXPECT_NEAR((s.point - Vec3(0.13, 0, 0)).norm(), 0, 1e-15);
  EXPECT_NEAR((s.normal - Vec3::UnitX()).norm(), 0, 1e-15);
  const std::uint32_t particle[5] = {0, 1, 2, 3, 3};
  const Real depth[5] = {0.002 + m, 0.008 + m, 0.0005 + m, 0.001 + m, 0.005 + m};
  ASSERT_EQ(contacts.size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) {
    EXPECT_EQ(contacts[k].particle, particle[k]) << k;
    EXPECT_NEAR(contacts[k].depth, depth[k], 1e-15) << k;
  }
  EXPECT_NEAR((contacts[4].normal + Vec3::UnitX()).norm(), 0, 1e-15);  // the x- face

  // Again from the same state: the same result, bit for bit.
  physics::Particles again = initial;
  std::vector<ToolContact> contacts2;
  const ContactSummary s2 = resolve_tool_contacts(again, start, tool, params, 0.01, contacts2);
  EXPECT_EQ(s2.count, s.count);
  EXPECT_EQ(s2.max_depth, s.max_depth);
  EXPECT_EQ(s2.point, s.point);
  EXPECT_EQ(s2.normal, s.normal);
  EXPECT_EQ(again.position, P.position);
  EXPECT_EQ(again.velocity, P.velocity);
  ASSERT_EQ(contacts2.size(), contacts.size());
  for (std::size_t k = 0; k < contacts.size(); ++k) {
    EXPECT_EQ(contacts2[k].particle, contacts[k].particle);
    EXPECT_EQ(contacts2[k].depth, contacts[k].depth);
    EXPECT_EQ(contacts2[k].point, contacts[k].point);
    EXPECT_EQ(contacts2[k].normal, contacts[k].normal);
  }
}

TEST(ToolContact, EquallyDeepContactsReportTheFirst) {
  physics::Particles P;
  P.add(Vec3(0.001, 0, 0.05), 0.001, 0);
  P.add(Vec3(-0.001, 0, 0.05), 0.001, 0);
  const std::vector<Vec3> start = P.position;
  std::vector<ToolContact> contacts;
  const ContactSummary s =
      resolve_tool_contacts(P, start, Shaft(), ContactParams(), 0.01, contacts);
  ASSERT_EQ(s.count, 2u);
  EXPECT_EQ(contacts[0].depth, contacts[1].depth);
  EXPECT_EQ(s.normal, Vec3::UnitX());
  EXPECT_EQ(s.point, contacts[0].point);
}

// A cloud of tissue around the forceps, the tool moving: twice from the same state gives the
// same positions, velocities and contacts, bit for bit.
TEST(ToolContact, CloudAroundTheForcepsIsDeterministic) {
  const InstrumentParams instrument;
  InstrumentState state;
  state.controller.rotation = axis_angle(Vec3(1, 1, 0), Real(0.4));
  state.controller.translation = Vec3(0, 0.01, 0.05);
  state.jaw_angle = degrees_to_radians(Real(20));
  ToolGeometry tool;
  make_tool_geometry(instrument, state, tool);
  tool.velocity = Vec3(0.02, -0.01, 0.03);
  const Real dt = 0.005;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<Real> u(-0.015, 0.015);
  physics::Particles P;
  std::vector<Vec3> start;
  for (int n = 0; n < 3000; ++n) {
    const Vec3 x = state.controller.translation + Vec3(u(rng), u(rng), u(rng));
    P.add(x, 0.001, static_cast<physics::ObjectId>(n % 11));
    start.push_back(x + Real(0.1) * Vec3(u(rng), u(rng), u(rng)));
  }
  const ContactParams params;
  physics::Particles first = P, second = P;
  std::vector<ToolContact> c1, c2;
  const ContactSummary s1 = resolve_tool_contacts(first, start, tool, params, dt, c1);
  const ContactSummary s2 = resolve_tool_contacts(second, start, tool, params, dt, c2);
  EXPECT_GT(s1.count, 50u);
  std::uint32_t total = 0;
  for (const std::uint32_t k : s1.per_object)
    total += k;
  EXPECT_EQ(total, s1.count);
  EXPECT_EQ(s1.count, s2.count);
  EXPECT_EQ(s1.max_depth, s2.max_depth);
  for (int k = 0; k < 8; ++k)
    EXPECT_EQ(s1.per_object[k], s2.per_object[k]);
  EXPECT_EQ(first.position, second.position);
  EXPECT_EQ(first.velocity, second.velocity);
  ASSERT_EQ(c1.size(), c2.size());
  for (std::size_t k = 0; k < c1.size(); ++k) {
    EXPECT_EQ(c1[k].particle, c2[k].particle);
    EXPECT_EQ(c1[k].depth, c2[k].depth);
    EXPECT_GT(c1[k].depth, 0);
    EXPECT_LE(c1[k].depth, s1.max_depth);
  }
  // Particles without contact keep their state, bit for bit.
  std::vector<bool> touched(P.size(), false);
  for (const ToolContact& c : c1)
    touched[c.particle] = true;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (touched[i]) continue;
    EXPECT_EQ(first.position[i], P.position[i]);
    EXPECT_EQ(first.velocity[i], P.velocity[i]);
  }
}

}  // namespace
}  // namespace imasim::surgery
