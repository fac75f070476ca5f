#pragma once
// The thorax scene: the thoracic-wall patch (tissue/thoracic_patch.hpp) with the beating heart
// under the left IMA and the ports. One step, in the order of the architecture: advance the
// heart (or hold it, static mode) and move the anchored boundary with it; engine step, XSPH,
// couplings; the heart as a collider; surfaces, the fine vessel and the strand ends.
#include <vector>

#include "physics/executor.hpp"
#include "physics/step.hpp"
#include "scene/ports.hpp"
#include "tissue/heart_field.hpp"
#include "tissue/thoracic_patch.hpp"

namespace imasim::scene {

struct ThoraxSceneParams {
  tissue::ThoracicPatchParams patch;
  tissue::HeartParams heart;
  tissue::HeartPlayback playback;
  std::vector<Port> ports;          // camera, left and right instrument, assistant
  Vec3 port_target = Vec3::Zero();  // where the ports aim (unit: m)
};

ThoraxSceneParams default_thorax_scene_params();

struct ThoraxScene {
  tissue::ThoracicPatch patch;
  tissue::HeartField heart;
  std::vector<Port> ports;
};

ThoraxScene make_thorax_scene(const ThoraxSceneParams& params);

physics::StepResult step_thorax_scene(ThoraxScene& scene, physics::Executor& exec);

}  // namespace imasim::scene
