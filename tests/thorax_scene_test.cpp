// The thorax scene: the heart keeps tissue out, drives the field, and the run is deterministic.
#include <gtest/gtest.h>

#include "physics/executor.hpp"
#include "scene/thorax_scene.hpp"

namespace imasim::scene {
namespace {

ThoraxScene make(bool beating) {
  ThoraxSceneParams p = default_thorax_scene_params();
  p.playback.beating = beating;
  return make_thorax_scene(p);
}

TEST(ThoraxScene, NoTissueParticleInsideTheHeartAfterSecondsOfBeating) {
  ThoraxScene s = make(true);
  physics::Executor exec(1);
  std::uint64_t contacts = 0;
  for (int n = 0; n < 600; ++n) {  // 3 s, nearly 4 beats
    ASSERT_TRUE(step_thorax_scene(s, exec).ok());
    contacts += s.heart.last_contacts;
    if (n % 50 != 49) continue;
    const physics::Particles& P = s.patch.world.state.particles;
    for (std::size_t i = 0; i < P.size(); ++i) {
      if (P.inverse_mass[i] == 0) continue;
      EXPECT_GE(tissue::heart_signed_distance(s.heart, P.position[i], 0.03), 0.0)
          << "particle " << i << " at step " << n;
    }
  }
  EXPECT_GT(contacts, 1000u);  // the heart did press on the tissue
}

// Largest displacement over the last beat of each IMA particle from its position at that beat's
// start, and the particle's distance from the heart.
std::vector<std::pair<double, double>> ima_motion(bool beating) {
  ThoraxScene s = make(beating);
  physics::Executor exec(2);
  for (int n = 0; n < 240; ++n)
    EXPECT_TRUE(step_thorax_scene(s, exec).ok());  // 1.5 beats
  const tissue::TissueWorld& w = s.patch.world;
  const tissue::MeshObject& ima = w.meshes[s.patch.ima];
  std::vector<Vec3> start(ima.particle_count);
  for (std::uint32_t k = 0; k < ima.particle_count; ++k)
    start[k] = w.state.particles.position[ima.first_particle + k];
  std::vector<std::pair<double, double>> out(ima.particle_count, {0.0, 0.0});
  for (int n = 0; n < 160; ++n) {  // one beat at 75 bpm
    EXPECT_TRUE(step_thorax_scene(s, exec).ok());
    for (std::uint32_t k = 0; k < ima.particle_count; ++k) {
      out[k].second =
          std::max(out[k].second,
                   double((w.state.particles.position[ima.first_particle + k] - start[k]).norm()));
    }
  }
  for (std::uint32_t k = 0; k < ima.particle_count; ++k) {
    out[k].first = tissue::heart_signed_distance(
        s.heart, w.state.particles.rest_position[ima.first_particle + k], 0.2);
  }
  return out;
}

TEST(ThoraxScene, HeartMotionReachesTheImaAndFallsWithDistance) {
  auto motion = ima_motion(true);
  std::sort(motion.begin(), motion.end());  // by distance from the heart
  const std::size_t third = motion.size() / 3;
  double near = 0, far = 0;
  for (std::size_t k = 0; k < third; ++k)
    near += motion[k].second / double(third);
  for (std::size_t k = motion.size() - third; k < motion.size(); ++k)
    far += motion[k].second / double(third);
  EXPECT_GT(near, 5e-4);       // sub-millimetre to millimetres of motion near the heart
  EXPECT_GT(near, 1.5 * far);  // less far from it
  EXPECT_GT(far, 0.0);
}

TEST(ThoraxScene, StaticHeartTransmitsNoMotion) {
  // Zero to rounding: what moves is rounding noise of the solver, relaxing by 0.8 a step.
  for (const auto& [distance, amplitude] : ima_motion(false)) {
    EXPECT_LT(amplitude, 1e-15);
  }
}

TEST(ThoraxScene, DeterministicAcrossThreadCountsAndHasItsPorts) {
  std::uint64_t hash[3];
  for (int t = 0; t < 3; ++t) {
    ThoraxScene s = make(true);
    physics::Executor exec(t == 2 ? 4 : t + 1);
    for (int n = 0; n < 60; ++n)
      ASSERT_TRUE(step_thorax_scene(s, exec).ok());
    hash[t] = physics::position_hash(s.patch.world.state);
    ASSERT_EQ(s.ports.size(), 4u);
    EXPECT_EQ(s.ports[0].kind, PortKind::camera);
    for (const Port& p : s.ports)
      EXPECT_NEAR(p.direction.norm(), 1.0, 1e-12);
  }
  EXPECT_EQ(hash[0], hash[1]);
  EXPECT_EQ(hash[0], hash[2]);
}

}  // namespace
}  // namespace imasim::scene
