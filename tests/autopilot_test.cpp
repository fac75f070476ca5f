// The scripted operator: its tremor, its playback through the device interface, and
// its plan on the default scene (made from the description alone, clear of the heart by a
// margin that grows with the heart's motion, clear of the vessel while the pedal is down).
#include <gtest/gtest.h>

#include <cmath>

#include "autopilot/harvest_plan.hpp"
#include "autopilot/scripted_operator.hpp"
#include "autopilot/tremor.hpp"
#include "autopilot/working_frame.hpp"
#include "geometry/closest_point.hpp"

namespace imasim::autopilot {
namespace {

session::SurgicalSession default_session(bool beating) {
  scene::ThoraxSceneParams params = scene::default_thorax_scene_params();
  params.playback.beating = beating;
  return session::make_surgical_session(params, session::SessionParams{});
}

Real distance_to_polyline(const Vec3& p, const std::vector<Vec3>& line) {
  Real best = 1e9;
  for (std::size_t i = 1; i < line.size(); ++i) {
    const Real u = geometry::closest_segment_parameter(p, line[i - 1], line[i]);
    best = std::min(best, (p - ((1 - u) * line[i - 1] + u * line[i])).norm());
  }
  return best;
}

TEST(Tremor, HasTheAskedRmsAndRepeatsForASeed) {
  const Tremor a(7, Real(2e-4)), b(7, Real(2e-4)), c(8, Real(2e-4));
  double sum2 = 0, mean = 0;
  const int n = 200000;
  for (int i = 0; i < n; ++i) {
    const double t = i * 1e-3;  // 200 s at 1 kHz: many periods of every wave
    const Vec3 x = a.at(t);
    sum2 += double(x.x() * x.x());
    mean += double(x.x());
    EXPECT_EQ(x, b.at(t));
  }
  EXPECT_NEAR(std::sqrt(sum2 / n), 2e-4, 2e-4 * 0.03);
  EXPECT_NEAR(mean / n, 0, 2e-6);
  EXPECT_NE(a.at(0.1234), c.at(0.1234));
  EXPECT_EQ(Tremor(3, 0).at(1.5), Vec3::Zero());
}

TEST(Tremor, IsPhysiologicalTremorOf8To12Hz) {
  // Over 1 s a band of 8-12 Hz crosses zero 16 to 24 times per axis (two crossings a period).
  const Tremor t(11, Real(1e-4));
  for (int axis = 0; axis < 3; ++axis) {
    int crossings = 0;
    for (int i = 1; i <= 10000; ++i) {
      const double t0 = (i - 1) * 1e-4, t1 = i * 1e-4;
      if ((t.at(t0)[axis] < 0) != (t.at(t1)[axis] < 0)) ++crossings;
    }
    EXPECT_GE(crossings, 14) << axis;  // beats between the waves may drop a crossing or two
    EXPECT_LE(crossings, 26) << axis;
  }
}

TEST(ToolTrack, InterpolatesPositionLinearlyAndRotationBySlerp) {
  std::vector<ToolKey> track(2);
  track[0].time = 1;
  track[1].time = 3;
  track[1].tool.translation = Vec3(0.02, -0.04, 0.06);
  track[1].tool.rotation = axis_angle(Vec3::UnitZ(), Real(1.2));
  track[1].jaw = 1;
  EXPECT_EQ(sample_tool_track(track, 0).tool.translation, Vec3::Zero());  // held before
  const ToolKey mid = sample_tool_track(track, 2);
  EXPECT_NEAR((mid.tool.translation - Vec3(0.01, -0.02, 0.03)).norm(), 0, 1e-15);
  EXPECT_NEAR((mid.tool.rotation - axis_angle(Vec3::UnitZ(), Real(0.6))).norm(), 0, 1e-12);
  EXPECT_DOUBLE_EQ(mid.jaw, 0.5);
  EXPECT_EQ(sample_tool_track(track, 9).tool.translation, track[1].tool.translation);
}

TEST(HarvestPlan, IsMadeFromTheDescriptionNotTheTissueState) {
  session::SurgicalSession s = default_session(true);
  const HarvestPlan before = plan_harvest(s, OperatorParams{});
  // Disturb the tissue (as a step would): the plan does not change.
  for (Vec3& x : s.scene.patch.world.state.particles.position)
    x += Vec3(0.003, -0.002, 0.001);
  const HarvestPlan after = plan_harvest(s, OperatorParams{});
  ASSERT_EQ(before.hook.size(), after.hook.size());
  for (std::size_t k = 0; k < before.hook.size(); ++k)
    EXPECT_EQ(before.hook[k].tool.translation, after.hook[k].tool.translation);
}

TEST(HarvestPlan, CoversTheSegmentInOrderAndKeepsClearOfHeartAndVessel) {
  const session::SurgicalSession s = default_session(true);
  const OperatorParams params;
  const HarvestPlan plan = plan_harvest(s, params);
  const WorkingFrame frame = make_working_frame(s, params.segment_length);
  EXPECT_NEAR(frame.length(), 0.10, 1e-3);
  ASSERT_EQ(plan.phases.size(), 4u);
  EXPECT_EQ(plan.phases[0].name, "open");
  EXPECT_EQ(plan.phases[1].name, "divide");
  EXPECT_EQ(plan.phases[2].name, "withdraw");
  EXPECT_EQ(plan.phases[3].name, "done");
  for (const auto* track : {&plan.forceps, &plan.hook})
    for (std::size_t k = 1; k < track->size(); ++k)
      EXPECT_LE((*track)[k - 1].time, (*track)[k].time);
  for (std::size_t k = 1; k < plan.pedal.size(); ++k)
    EXPECT_LE(plan.pedal[k - 1].time, plan.pedal[k].time);
  EXPECT_GT(plan.heart_excursion, 0.001);  // the beating heart moves under the segment
  EXPECT_DOUBLE_EQ(plan.keep_out,
                   params.keep_out_base + params.keep_out_gain * plan.heart_excursion);
  const Real electrode = s.params.cautery.electrode_length;
  bool reached_distal_end = false, reached_proximal_end = false;
  for (const ToolKey& k : plan.hook) {
    const Vec3 tip = k.tool.translation + electrode * k.tool.rotation.col(2);
    reached_distal_end = reached_distal_end || (tip - plan.segment.back()).norm() < 0.012;
    reached_proximal_end = reached_proximal_end || (tip - plan.segment.front()).norm() < 0.012;
  }
  EXPECT_TRUE(reached_distal_end);
  EXPECT_TRUE(reached_proximal_end);
  // While the pedal is down the electrode's tip (as the arm gives it: the wrist bends at most
  // so far from the shaft) keeps its distance from the vessel.
  ScriptedOperator op(plan, OperatorParams{.tremor = 0});
  devices::ConsoleInput in;
  Real closest = 1;
  for (double t = 0; t < plan.end_time; t += 0.005) {
    op.poll(t, in);
    if (in.pedal == haptics::CauteryMode::off) continue;
    const Pose hook = surgery::constrain_to_port(frame.hook_arm, in.right.pose);
    closest = std::min(
        closest,
        distance_to_polyline(hook.translation + electrode * hook.rotation.col(2), plan.segment));
  }
  // The dividing sweep puts the tip 3.2 mm from the centre (2.5 mm beside, 2 mm over): about
  // 2 mm from the wall of the vessel's 1.25 mm radius; never closer than 3 mm.
  EXPECT_GE(closest, 0.003);
}

// The hinge of every forceps key except while it waits at its set-up pose (the scene places it,
// not the operator).
std::vector<Vec3> forceps_points(const HarvestPlan& plan) {
  std::vector<Vec3> points;
  for (const ToolKey& k : plan.forceps)
    if (k.tool.translation != plan.forceps.front().tool.translation)
      points.push_back(k.tool.translation);
  return points;
}

TEST(HarvestPlan, KeepsFurtherFromABeatingHeartThanFromAStillOne) {
  const session::SurgicalSession beating_session = default_session(true);
  const HarvestPlan beating = plan_harvest(beating_session, OperatorParams{});
  const HarvestPlan still = plan_harvest(default_session(false), OperatorParams{});
  EXPECT_EQ(still.heart_excursion, 0);
  EXPECT_DOUBLE_EQ(still.keep_out, OperatorParams{}.keep_out_base);
  EXPECT_GT(beating.keep_out, still.keep_out + 0.001);
  // The forceps keep each plan's margin (the hook keeps it too where the chest wall leaves room
  // over it); with the beating heart's larger margin the tools stay further out on average.
  const WorkingFrame frame = make_working_frame(beating_session, Real(0.1));
  const auto closest = [&](const HarvestPlan& p) {
    Real c = 1;
    for (const Vec3& x : forceps_points(p))
      c = std::min(c, frame.heart_distance(x));
    return c;
  };
  EXPECT_GE(closest(still), still.keep_out * (1 - 1e-9));
  EXPECT_GE(closest(beating), beating.keep_out * (1 - 1e-9));
  const auto mean_distance = [&](const HarvestPlan& p) {
    double sum = 0;
    for (const ToolKey& k : p.hook)
      sum += double(frame.heart_distance(k.tool.translation));
    return sum / double(p.hook.size());
  };
  EXPECT_GT(mean_distance(beating), mean_distance(still) + 1e-4);
  const Real electrode = beating_session.params.cautery.electrode_length;
  // Its working lines are higher (towards the wall, away from the heart) on average.
  // (The electrode's tips as the arm gives them: the hinges move with the wrist's limit.)
  const auto mean_height = [&](const HarvestPlan& p) {
    double sum = 0;
    for (const ToolKey& k : p.hook) {
      const Pose hook = surgery::constrain_to_port(frame.hook_arm, k.tool);
      const Vec3 tip = hook.translation + electrode * hook.rotation.col(2);
      sum += double((tip - frame.point_at(frame.length() / 2)).dot(frame.wall_normal));
    }
    return sum / double(p.hook.size());
  };
  // The dividing sweeps rise by the margin up to the wall's clearance (here 0.5 mm, the wall 4 mm
  // over the vessel), about half of the plan.
  EXPECT_GT(mean_height(beating), mean_height(still) + 2e-4);
}

// A virtual patient whose heart comes within 4.6 mm of the IMA's centre, the chest wall 4.9 mm
// over it: an upright hook (its electrode rising 7.2 mm) spans the gap there.
TEST(HarvestPlan, LaysTheHookFlatterWhereTheHeartComesNearTheWall) {
  scene::ThoraxSceneParams params = scene::default_thorax_scene_params();
  params.playback.beating = false;
  params.anatomy.patient_seed = 3301373580649648360u;
  const session::SurgicalSession s = session::make_surgical_session(params, {});
  const OperatorParams op;
  const HarvestPlan plan = plan_harvest(s, op);
  const WorkingFrame frame = make_working_frame(s, op.segment_length);
  const Real electrode = s.params.cautery.electrode_length;
  const double divide = plan.phases[1].time, withdraw = plan.phases[2].time;
  ASSERT_EQ(plan.phases[1].name, "divide");
  Real closest = 1;
  int flatter = 0;
  for (const ToolKey& k : plan.hook) {
    if (k.time < divide || k.time >= withdraw) continue;
    const Pose hook = surgery::constrain_to_port(frame.hook_arm, k.tool);
    for (const Real along : {Real(0), Real(0.5), Real(1)})
      closest = std::min(closest, frame.heart_distance(hook.translation +
                                                       along * electrode * hook.rotation.col(2)));
    flatter += k.tool.rotation.col(2).dot(frame.wall_normal) < Real(0.85);
  }
  // While it divides, the hook's hinge, electrode and tip keep (nearly) the operator's base margin
  // from the heart: measured 1.97 mm, where the upright hook came within 0.03 mm.
  EXPECT_GE(closest, Real(0.9) * op.keep_out_base);
  EXPECT_GT(flatter, 0);
}

TEST(ScriptedOperator, DrivesOnlyTheDeviceInterface) {
  const session::SurgicalSession s = default_session(false);
  const HarvestPlan plan = plan_harvest(s, OperatorParams{});
  ScriptedOperator op(plan, OperatorParams{});
  devices::ConsoleInput in;
  int cutting = 0, closed = 0;
  for (double t = 0; t <= plan.end_time; t += 0.01) {
    op.poll(t, in);
    for (const devices::HandInput* h : {&in.left, &in.right}) {
      EXPECT_TRUE(h->has_pose);
      EXPECT_EQ(h->frame, devices::PoseFrame::tool);
      EXPECT_TRUE(h->pose.translation.allFinite());
      EXPECT_NEAR((h->pose.rotation.transpose() * h->pose.rotation - Mat3::Identity()).norm(), 0,
                  1e-9);
      EXPECT_GE(h->jaw, 0);
      EXPECT_LE(h->jaw, 1);
    }
    cutting += in.pedal == haptics::CauteryMode::cut;
    closed += in.left.jaw > Real(0.9);
  }
  EXPECT_GT(cutting, 1000);  // 10 cm opened and divided at 10 mm/s: tens of seconds
  EXPECT_GT(closed, 100);    // the forceps hold the lip in every section
  EXPECT_TRUE(op.finished(plan.end_time));
  EXPECT_EQ(op.phase_at(plan.end_time), "done");
  EXPECT_EQ(op.info().kind, "autopilot");
}

TEST(ScriptedOperator, CorrectsItsHandsForWhereItSeesTheInstrumentsGo) {
  // One key: the plan holds a pose. The instrument is seen 3 mm short of where the hand asks
  // (as tissue pressing on the proxy would hold it): the hand moves on until the instrument is
  // where the plan wants it.
  HarvestPlan plan;
  plan.forceps = plan.hook = {ToolKey{0, Pose{}, 0}};
  plan.forceps[0].tool.translation = plan.hook[0].tool.translation = Vec3(0.01, 0.02, 0.03);
  plan.end_time = 10;
  ScriptedOperator op(plan, OperatorParams{.tremor = 0});
  const Vec3 held_back(0, 0, -0.003);
  devices::ConsoleInput in;
  for (int k = 0; k < 200; ++k) {
    op.observe(devices::Hand::right,
               Pose{in.right.pose.rotation, in.right.pose.translation + held_back});
    op.poll(0.005 * k, in);
  }
  EXPECT_NEAR((in.right.pose.translation + held_back - plan.hook[0].tool.translation).norm(), 0,
              1e-9);
  // Unobserved, the left hand plays the plan as it is.
  EXPECT_EQ(in.left.pose.translation, plan.forceps[0].tool.translation);
  // A tool that never moves (the heart stops it) is not pushed after by more than 10 mm.
  for (int k = 0; k < 400; ++k) {
    op.observe(devices::Hand::right, Pose{Mat3::Identity(), Vec3(0.01, 0.02, 0.0)});
    op.poll(1 + 0.005 * k, in);
  }
  EXPECT_NEAR((in.right.pose.translation - plan.hook[0].tool.translation).norm(), 0.01, 1e-12);
}

TEST(ScriptedOperator, KeepsThePedalUpOnlyWhileTheHookIsPushedTowardsTheVessel) {
  // The vessel runs along z through the origin; the plan holds the hook's hinge 5 mm beside it,
  // its 8 mm electrode along z (tip 5 mm from the vessel), the pedal on cut throughout.
  HarvestPlan plan;
  plan.segment = {Vec3(0, 0, 0), Vec3(0, 0, 0.1)};
  plan.electrode_length = Real(0.008);
  plan.forceps = plan.hook = {ToolKey{0, Pose{}, 0}};
  plan.hook[0].tool.translation = Vec3(0.005, 0, 0.05);
  plan.pedal = {PedalKey{0, haptics::CauteryMode::cut, 30}};
  plan.end_time = 10;
  const auto pedal_when_seen_off_by = [&](const Vec3& held) {
    ScriptedOperator op(plan, OperatorParams{.tremor = 0});
    devices::ConsoleInput in;
    op.poll(0, in);  // asks for the plan's pose
    op.observe(devices::Hand::right, Pose{Mat3::Identity(), plan.hook[0].tool.translation + held});
    op.poll(0.005, in);
    return in.pedal;
  };
  using haptics::CauteryMode;
  EXPECT_EQ(pedal_when_seen_off_by(Vec3::Zero()), CauteryMode::cut);
  // Held 3 mm back away from the vessel (caught on what it divides): it cuts on.
  EXPECT_EQ(pedal_when_seen_off_by(Vec3(0.003, 0, 0)), CauteryMode::cut);
  EXPECT_EQ(pedal_when_seen_off_by(Vec3(0, 0.003, 0)), CauteryMode::cut);  // further, sideways
  // Pushed 3 mm towards the vessel: the pedal goes up.
  EXPECT_EQ(pedal_when_seen_off_by(Vec3(-0.003, 0, 0)), CauteryMode::off);
  // Within 2.5 mm of its line the hook is where the operator sees it should be.
  EXPECT_EQ(pedal_when_seen_off_by(Vec3(-0.002, 0, 0)), CauteryMode::cut);
}

TEST(HarvestPlan, RefusesParametersOutOfRange) {
  const session::SurgicalSession s = default_session(false);
  EXPECT_THROW(plan_harvest(s, OperatorParams{.speed = 0}), std::invalid_argument);
  EXPECT_THROW(plan_harvest(s, OperatorParams{.tremor = Real(NAN)}), std::invalid_argument);
  EXPECT_THROW(plan_harvest(s, OperatorParams{.segment_length = Real(0.5)}), std::invalid_argument);
}

}  // namespace
}  // namespace imasim::autopilot
