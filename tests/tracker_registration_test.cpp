// A tracker's frame and its registration: every OpenIGTLink pose is taken into
// the scene's frame by devices.tracker_translation_m and tracker_rotation_deg; a tool pose under
// devices.tool_registration = "clutch" moves the tool by how far the tracker moved since its
// first pose or the last clutch release, 1:1, instead of placing it where the tracker's frame
// says; the haptic local model follows the same anchors.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <numbers>

#include "console/console_settings_use.hpp"
#include "console/local_model_of.hpp"
#include "devices/igtl_codec.hpp"
#include "haptics/local_model.hpp"
#include "physics/executor.hpp"
#include "scene/thorax_scene.hpp"

namespace imasim {
namespace {

constexpr Real kDegree = std::numbers::pi_v<Real> / 180;

TEST(TrackerFrame, APoseArrivesInTheScenesFrame) {
  scene::ConsoleSettings settings;
  settings.tracker_rotation_deg = Vec3(0, 0, 90);  // the tracker's x is the scene's y
  settings.tracker_translation = Vec3(0, 0, 0.1);
  devices::IgtlDecoder decoder;
  decoder.set_tracker_to_scene(console::tracker_to_scene(settings));
  Pose tracked;
  tracked.translation = Vec3(0.01, 0, 0);
  const std::vector<std::uint8_t> m = devices::encode_pose("LeftTool", tracked, 1.0);
  devices::ConsoleInput input;
  ASSERT_TRUE(decoder.apply(m.data(), m.data() + devices::kIgtlHeaderBytes,
                            m.size() - devices::kIgtlHeaderBytes, input));
  EXPECT_LT((input.left.pose.translation - Vec3(0, 0.01, 0.1)).norm(), 1e-6);
  EXPECT_LT((input.left.pose.rotation -
             Eigen::AngleAxis<Real>(90 * kDegree, Vec3::UnitZ()).toRotationMatrix())
                .cwiseAbs()
                .maxCoeff(),
            1e-6);
}

TEST(TrackerFrame, TheRotationTurnsAboutXThenYThenZ) {
  scene::ConsoleSettings settings;
  settings.tracker_rotation_deg = Vec3(90, 90, 0);
  // x first: the y axis goes to z; then y: z goes to x.
  const Pose p = console::tracker_to_scene(settings);
  EXPECT_LT((p.rotation * Vec3::UnitY() - Vec3::UnitX()).norm(), 1e-6);
  EXPECT_TRUE(p.translation.isZero());
}

struct Sessions {
  explicit Sessions(session::SurgicalSession s) : session(std::move(s)) {}
  session::SurgicalSession session;
  physics::Executor exec{1};
};

std::unique_ptr<Sessions> make_session(const std::string& registration) {
  scene::ThoraxSceneParams params = scene::default_thorax_scene_params();
  params.console.tool_registration = registration;
  params.playback.beating = false;
  return std::make_unique<Sessions>(
      session::make_surgical_session(params, session::SessionParams{}));
}

// Steps with the hook's tool pose at `tracked` (clutch as given), and returns the hook's
// commanded pose.
Vec3 step_with_tool_pose(Sessions& s, const Vec3& tracked, bool clutch, int steps = 3) {
  session::SessionInput in;
  in.right.source = surgery::PoseSource::tool;
  in.right.pose.translation = tracked;
  in.right.pose.rotation = s.session.stations[1].arm_state.tool.rotation;
  in.right.clutch = clutch;
  for (int k = 0; k < steps; ++k)
    EXPECT_TRUE(session::step_session(s.session, in, s.exec).ok());
  return s.session.stations[1].arm_state.commanded.translation;
}

TEST(ToolRegistration, AClutchRegisteredTrackerMovesTheToolFromWhereItIs) {
  const auto s = make_session("clutch");
  const Vec3 start = s->session.stations[1].arm_state.tool.translation;
  // The tracker's frame is 30 cm away from the scene's: the first pose registers, no jump.
  const Vec3 far(0.3, 0.2, -0.1);
  EXPECT_LT((step_with_tool_pose(*s, far, false) - start).norm(), 1e-9);
  // Moved 5 mm along x: the tool moves 5 mm along x (1:1).
  EXPECT_LT((step_with_tool_pose(*s, far + Vec3(0.005, 0, 0), false) - (start + Vec3(0.005, 0, 0)))
                .norm(),
            1e-9);
  // Clutched, the tracker goes back 4 cm: the tool holds; released there, it goes on from where
  // it held.
  const Vec3 held = s->session.stations[1].arm_state.commanded.translation;
  EXPECT_LT((step_with_tool_pose(*s, far + Vec3(-0.035, 0, 0), true) - held).norm(), 1e-9);
  EXPECT_LT((step_with_tool_pose(*s, far + Vec3(-0.035, 0, 0), false) - held).norm(), 1e-9);
  EXPECT_LT(
      (step_with_tool_pose(*s, far + Vec3(-0.035, 0.002, 0), false) - (held + Vec3(0, 0.002, 0)))
          .norm(),
      1e-9);
  // The haptic loop's model maps the tracker the same way: the device at the tracker's pose is
  // at the commanded tool.
  const haptics::LocalModel m = console::local_model_of(s->session, 1, 0, 1);
  EXPECT_EQ(m.motion_scale, 1);
  const Vec3 device =
      m.tool_anchor + m.motion_scale * (far + Vec3(-0.035, 0.002, 0) - m.hand_anchor);
  EXPECT_LT((device - s->session.stations[1].arm_state.commanded.translation).norm(), 1e-9);
}

TEST(ToolRegistration, AFixedTrackerPlacesTheToolWhereItSays) {
  const auto s = make_session("fixed");
  const Vec3 start = s->session.stations[1].arm_state.tool.translation;
  const Vec3 there = start + Vec3(0.004, -0.003, 0.002);
  EXPECT_LT((step_with_tool_pose(*s, there, false) - there).norm(), 1e-9);
  // The clutch does not hold a fixed tracker's tool: it is where the tracker is.
  EXPECT_LT((step_with_tool_pose(*s, there + Vec3(0.002, 0, 0), true) - (there + Vec3(0.002, 0, 0)))
                .norm(),
            1e-9);
}

}  // namespace
}  // namespace imasim
