// What the recorder samples from a session (console/trajectory_sample.hpp): the tips where the
// instruments work, and the force the hand is given (eq. 17) from the step's local model with the
// device where the hand asked.
#include "console/trajectory_sample.hpp"

#include <gtest/gtest.h>

#include "scene/thorax_scene.hpp"
#include "session/tool_tip.hpp"

namespace imasim::console {
namespace {

TEST(TrajectorySample, TipsAreTheJawsMidpointAndTheElectrodesEnd) {
  const session::SurgicalSession s =
      session::make_surgical_session(scene::default_thorax_scene_params(), {});
  const Vec3 upper =
      surgery::jaw_tip(s.stations[0].instrument,
                       surgery::upper_jaw_pose(s.stations[0].instrument, s.stations[0].state));
  const Vec3 lower =
      surgery::jaw_tip(s.stations[0].instrument,
                       surgery::lower_jaw_pose(s.stations[0].instrument, s.stations[0].state));
  EXPECT_LT((session::tool_tip(s, 0) - Real(0.5) * (upper + lower)).norm(), 1e-15);
  const std::array<Vec3, 2> e = session::electrode(s);
  EXPECT_LT((session::tool_tip(s, 1) - e[1]).norm(), 1e-15);
  const metrics::TrajectorySample t = trajectory_sample(s, haptics::default_force_model_params());
  EXPECT_EQ(t.tools[0].tip, session::tool_tip(s, 0));
  EXPECT_EQ(t.tools[1].tip, session::tool_tip(s, 1));
  EXPECT_EQ(t.tools[1].force_normal, 0);  // nothing touched
  EXPECT_EQ(t.pedal, surgery::PedalMode::off);
}

TEST(TrajectorySample, TheForceIsEquationSeventeenAtTheDevicesDepth) {
  session::SurgicalSession s =
      session::make_surgical_session(scene::default_thorax_scene_params(), {});
  session::Station& hook = s.stations[1];
  // The proxy held 2 mm short of the device by fascia pushing back along +y, at rest.
  hook.proxy.pressed = surgery::Tissue::fascia;
  hook.proxy.tissue_force = Vec3(0, 0.6, 0);
  hook.proxy.normal_force = Vec3(0, 0.6, 0);  // the contacts' normal push: no friction
  hook.device = hook.pose;
  hook.device.translation = hook.state.controller.translation - Vec3(0, 0.002, 0);
  hook.previous_pose = hook.pose;
  hook.pedal = surgery::PedalMode::cut;
  hook.power_w = 30;
  const haptics::ForceModelParams law = haptics::default_force_model_params();
  const metrics::TrajectorySample t = trajectory_sample(s, law);
  EXPECT_NEAR(t.tools[1].force_normal, law.of(haptics::TissueKind::fascia).stiffness * 0.002,
              1e-12);
  EXPECT_EQ(t.tools[1].contact, surgery::Tissue::fascia);
  EXPECT_GT(t.tools[1].force_thermal, 0);  // cutting: eq. 19's thermal channel is on
  EXPECT_EQ(t.pedal, surgery::PedalMode::cut);
  EXPECT_EQ(t.power_w, 30);
  EXPECT_LT((t.tools[1].device - hook.device.translation).norm(), 1e-15);
}

}  // namespace
}  // namespace imasim::console
