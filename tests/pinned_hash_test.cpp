// Replays move between machines (Box2D's test_determinism.c): in the portable build (no
// -march=native, no floating-point contraction) the state hashes of a cloth and of a scripted
// session are pinned. A change of these numbers is a change of the simulation's results: make it
// on purpose, say why in the commit, and update the numbers here. Native builds may use wider
// vector units whose sums round differently, so they only check run-to-run repeatability
// (determinism_test.cpp).
#include <gtest/gtest.h>

#include <cstdio>

#include "physics/executor.hpp"
#include "physics/step.hpp"
#include "scene/cloth_scene.hpp"
#include "session/surgical_session.hpp"
#include "surgery/input_script.hpp"

namespace imasim {
namespace {

#if IMASIM_PORTABLE && !IMASIM_REAL_FLOAT
constexpr bool kPortable = true;
#else
constexpr bool kPortable = false;
#endif

constexpr std::uint64_t kClothHash = 0x4b3e03bcb505667dull;
constexpr std::uint64_t kSessionHash = 0xf9ab6c904c402c93ull;

std::string hex(std::uint64_t h) {
  char text[20];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(h));
  return text;
}

std::uint64_t cloth_hash(int threads) {
  scene::ClothParams p;
  p.n = 48;
  p.response = physics::Response::xpbd;
  p.distance_compliance = 1e-6;
  p.bending_compliance = 1e-2;
  p.substeps = 4;
  p.iterations = 2;
  p.linear_damping = 0.03;
  scene::ClothScene s = scene::make_cloth_scene(p);
  physics::Executor exec(threads);
  for (int n = 0; n < 100; ++n)
    EXPECT_TRUE(physics::step(s.model, s.state, exec).ok());
  return physics::position_hash(s.state);
}

// The example script's first 1.2 s: the approach and the first cut of the fascia.
std::uint64_t session_hash(int threads) {
  const surgery::InputScript script =
      surgery::load_input_script(IMASIM_SOURCE_DIR "/examples/open_fascia.script");
  session::SurgicalSession s = session::make_surgical_session(scene::default_thorax_scene_params(),
                                                              session::SessionParams{});
  physics::Executor exec(threads);
  tissue::TissueWorld& w = s.scene.patch.world;
  for (int n = 0; n < 240; ++n) {
    const physics::StepResult r =
        session::step_session(s, session::sample_script(script, w.state.time), exec);
    EXPECT_TRUE(r.ok());
    if (!r.ok()) break;
  }
  return physics::position_hash(w.state);
}

TEST(PinnedHash, ClothStateMatchesThePortableBuildsHash) {
  const std::uint64_t h = cloth_hash(2);
  if (!kPortable) GTEST_SKIP() << "native build (hash " << hex(h) << "): pinned in portable builds";
  EXPECT_EQ(hex(h), hex(kClothHash));
}

TEST(PinnedHash, ScriptedSessionStateMatchesThePortableBuildsHash) {
  const std::uint64_t h = session_hash(2);
  if (!kPortable) GTEST_SKIP() << "native build (hash " << hex(h) << "): pinned in portable builds";
  EXPECT_EQ(hex(h), hex(kSessionHash));
}

}  // namespace
}  // namespace imasim
