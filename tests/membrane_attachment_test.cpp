// The implicit membrane's attachments (physics/implicit_membrane.hpp): a vertex held by a tool's
// grasp, a stiff spring to a target riding on the tool's body, solved with the membrane and the
// body (the forceps holding the fascia when it is solved implicitly). Closed forms: at rest the
// holds and the body's coupling carry the weight they hold.
#include <gtest/gtest.h>

#include "physics/implicit_membrane.hpp"

namespace imasim::physics {
namespace {

const Vec3 kGravity(0, -9.81, 0);
constexpr double kMass = 0.002;  // (unit: kg)

TEST(MembraneAttachment, AVertexHeldByAFixedTargetHangsWhereTheHoldCarriesItsWeight) {
  ImplicitMembrane point({kMass}, {0}, {}, 0.005);
  std::vector<Vec3> x = {Vec3::Zero()}, v = {Vec3::Zero()};
  const double k = 50;  // (unit: N/m)
  const std::vector<MembraneAttachment> hold = {{0, Vec3::Zero(), kNoMembraneBody, k}};
  const ImplicitSolveParams solve;
  for (int step = 0; step < 400; ++step)
    ASSERT_TRUE(point.step(x, v, {kGravity, {}, {}, {}, hold}, solve).ok);
  // m g / k below the target, to the solve's tolerance (1e-6 N over 50 N/m: 2e-8 m).
  EXPECT_NEAR(x[0].y(), -kMass * 9.81 / k, 1e-7);
  EXPECT_NEAR(attachment_pull(hold[0], x[0]).y(), -kMass * 9.81, 1e-6);
}

TEST(MembraneAttachment, AHeldVertexPullsTheToolsBodyDownByItsWeight) {
  // The vertex held by a grasp (1e6 N/m, the XPBD hold's compliance 1e-6 m/N) on a body coupled
  // to its device by eq. 17's spring and damper (1000 N/m, 5 N s/m): at rest the body sags m g / k
  // below the device, and the vertex hangs m g / k_hold below the target the body carries.
  ImplicitMembrane point({kMass}, {0}, {}, 0.005, {}, 1);
  const Vec3 target(0.01, 0.02, 0.03);
  std::vector<Vec3> x = {target}, v = {Vec3::Zero()};
  std::vector<MembraneBody> body = {{Vec3::Zero(), 1000, 5, Vec3::Zero()}};
  const std::vector<MembraneAttachment> hold = {{0, target, 0, 1e6}};
  const ImplicitSolveParams solve;
  for (int step = 0; step < 200; ++step) {
    const Vec3 start = body[0].position;
    std::vector<MembraneAttachment> carried = hold;  // the target where the body starts the step
    carried[0].target = target + start;
    ASSERT_TRUE(point.step(x, v, {kGravity, {}, {}, body, carried}, solve).ok);
  }
  const double weight = kMass * 9.81;
  EXPECT_NEAR(body[0].position.y(), -weight / 1000, 1e-9);
  EXPECT_NEAR(body[0].position.x(), 0, 1e-12);
  EXPECT_NEAR(x[0].y(), target.y() - weight / 1000 - weight / 1e6, 1e-9);
  EXPECT_NEAR(v[0].norm(), 0, 1e-6);
}

// The tool's body pressed on a surface (the chest wall) by its coupling: its device 2 mm beyond
// the plane, the body stops on it, 2 N over the stop's 1e7 N/m (0.2 um inside), and the vertex it
// holds stays on the hold's target, which rides with the body.
TEST(MembraneAttachment, ABodyStoppedByASurfaceStaysOnItWithWhatItHolds) {
  ImplicitMembrane point({kMass}, {0}, {}, 0.005, {}, 1);
  const Vec3 target(0, 0.001, 0);
  std::vector<Vec3> x = {target}, v = {Vec3::Zero()};
  // The device 2 mm below the stop's plane y = 0 (out of the surface: +y).
  std::vector<MembraneBody> body = {{Vec3(0, -0.002, 0), 1000, 5, Vec3::Zero()}};
  const ImplicitSolveParams solve;
  for (int step = 0; step < 200; ++step) {
    const Vec3 start = body[0].position;
    const std::vector<MembraneAttachment> hold = {{0, target + start, 0, 1e6}};
    const std::vector<MembraneBodyStop> stop = {{0, Vec3::UnitY(), start.y()}};
    ImplicitLoads loads{Vec3::Zero(), {}, {}, body, hold};
    loads.body_stops = stop;
    ASSERT_TRUE(point.step(x, v, loads, solve).ok);
  }
  const double push = 1000 * 0.002;  // the spring's, k |o - anchor| with o on the plane
  EXPECT_NEAR(body[0].position.y(), -push / solve.body_stop_stiffness, 1e-9);
  EXPECT_NEAR((x[0] - (target + body[0].position)).norm(), 0, 1e-12);
  // Without the stop the body reaches its device.
  std::vector<MembraneBody> free_body = {{Vec3(0, -0.002, 0), 1000, 5, Vec3::Zero()}};
  x = {target};
  for (int step = 0; step < 200; ++step) {
    const std::vector<MembraneAttachment> hold = {{0, target + free_body[0].position, 0, 1e6}};
    ASSERT_TRUE(point.step(x, v, {Vec3::Zero(), {}, {}, free_body, hold}, solve).ok);
  }
  EXPECT_NEAR(free_body[0].position.y(), -0.002, 1e-6);
}

TEST(MembraneAttachment, RefusesAnAttachmentOutOfRangeOrWithoutStiffness) {
  ImplicitMembrane point({kMass}, {0}, {}, 0.005);
  std::vector<Vec3> x = {Vec3::Zero()}, v = {Vec3::Zero()};
  const ImplicitSolveParams solve;
  for (const MembraneAttachment& bad :
       {MembraneAttachment{1, Vec3::Zero(), kNoMembraneBody, 10},
        MembraneAttachment{0, Vec3::Zero(), 0, 10},  // the solver has no body
        MembraneAttachment{0, Vec3::Zero(), kNoMembraneBody, 0}}) {
    const std::vector<MembraneAttachment> holds = {bad};
    EXPECT_THROW(point.step(x, v, {kGravity, {}, {}, {}, holds}, solve), std::invalid_argument);
  }
  const std::vector<MembraneBodyStop> stop = {{0, Vec3::UnitY(), 0}};  // no body to stop
  EXPECT_THROW(point.step(x, v, {kGravity, {}, {}, {}, {}, stop}, solve), std::invalid_argument);
}

}  // namespace
}  // namespace imasim::physics
