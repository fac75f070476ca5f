#include "scene/thorax_scene.hpp"

#include "tissue/tissue_step.hpp"

namespace imasim::scene {

ThoraxSceneParams default_thorax_scene_params() {
  ThoraxSceneParams p;
  p.patch = tissue::default_thoracic_patch_params();
  // The heart lies under the left IMA, in the cavity (-y), its free wall touching the fascia's
  // fat and pressing into them as it fills: LV centre 38 mm from the wall, radius 26 mm.
  p.heart.centre = Vec3(Real(0.005), Real(-0.038), Real(0.09));
  p.port_target = Vec3(0, Real(-0.004), Real(0.075));  // middle of the harvest segment
  p.ports = default_ports(p.port_target);
  return p;
}

ThoraxScene make_thorax_scene(const ThoraxSceneParams& params) {
  ThoraxScene scene;
  scene.patch = tissue::make_thoracic_patch(params.patch);
  scene.heart =
      tissue::make_heart_field(tissue::make_procedural_heart(params.heart), params.playback);
  tissue::TissueWorld& w = scene.patch.world;
  // Deep tissues anchored to the heart's motion: the chest wall, the vessel and the fat around
  // it, and the fascia (whose fixed perimeter is its anchor).
  tissue::add_heart_anchors(scene.heart, w, {scene.patch.wall, scene.patch.ima, scene.patch.fascia},
                            {scene.patch.ima_fat});
  tissue::advance_heart(scene.heart, w, w.state.time);
  // Tissue generated at rest may start inside the heart: put it out once, with a wide search.
  tissue::collide_with_heart(scene.heart, w.state.particles, w.state.particles.position,
                             Real(0.03));
  tissue::finish_tissue_step(w);
  scene.ports = params.ports;
  aim_ports(scene.ports, params.port_target);
  return scene;
}

physics::StepResult step_thorax_scene(ThoraxScene& scene, physics::Executor& exec) {
  tissue::TissueWorld& w = scene.patch.world;
  // The heart at the end of this step's interval drives the boundary for the step.
  tissue::advance_heart(scene.heart, w, w.state.time + double(w.model.solver.dt));
  const physics::StepResult r = tissue::step_tissue_dynamics(w, exec);
  if (!r.ok()) return r;
  // Positions at the start of the step: the physics step saved them (state.scratch).
  tissue::collide_with_heart(scene.heart, w.state.particles, w.state.scratch.saved_position);
  tissue::finish_tissue_step(w);
  return r;
}

}  // namespace imasim::scene
