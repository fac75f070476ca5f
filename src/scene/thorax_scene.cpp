#include "scene/thorax_scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "math/stopwatch.hpp"
#include "scene/heart_placement.hpp"
#include "tissue/tissue_step.hpp"

namespace imasim::scene {

ThoraxSceneParams default_thorax_scene_params() {
  ThoraxSceneParams p;
  p.patch = tissue::default_thoracic_patch_params();
  const ThoraxLayout layout = layout_thorax(p.anatomy, p.heart.long_axis, p.heart.lateral);
  p.port_target = layout.ima_midpoint;  // middle of the harvest segment
  p.ports = default_ports(p.port_target);
  // On the typical patient's left chest wall, 8-11 cm lateral of the midline, the pivot 1 cm
  // into the wall; the ports are the surgeon's placement, fixed in the room, so a varied
  // patient (patient_seed) does not move them. Order: camera, left, right, assistant.
  const Real lateral[4] = {Real(0.10), Real(0.105), Real(0.095), Real(0.115)};
  const Real level[4] = {Real(0.08), Real(0.0), Real(0.16), Real(0.2)};
  for (std::size_t k = 0; k < p.ports.size() && k < 4; ++k) {
    const Real x = p.anatomy.sternum_position.x() + lateral[k];
    p.ports[k].position = wall_point(p.anatomy, x, p.anatomy.sternum_position.z() + level[k]) +
                          Real(0.01) * wall_outward_normal(p.anatomy, x);
  }
  aim_ports(p.ports, p.port_target);
  return p;
}

tissue::ThoracicPatchParams lay_out_patch(const ThoraxSceneParams& params,
                                          const AnatomyParams& patient,
                                          const ThoraxLayout& layout) {
  tissue::ThoracicPatchParams patch = params.patch;
  const std::uint32_t nu = patch.wall.nu, nv = patch.wall.nv;
  patch.wall = layout.wall;
  patch.wall.nu = nu, patch.wall.nv = nv;
  patch.vessel.centerline = layout.ima_centerline;
  patch.fascia.width = patient.fascia_width;
  patch.fascia.height = patient.fascia_length;
  patch.fascia.pose = layout.fascia_pose;
  patch.ima_fat.generation.max_length =
      params.ima_fat_reach * (patient.ima_depth - patch.vessel.radius);
  patch.fascia_fat.generation.max_length = params.fascia_fat_reach * patient.fat_thickness;
  return patch;
}

namespace {

// The procedural heart's parameters for the scene's layout and patient.
tissue::HeartParams builtin_heart(const ThoraxSceneParams& params, const ThoraxScene& scene) {
  tissue::HeartParams heart = params.heart;
  heart.centre = scene.layout.heart_centre;
  heart.long_axis = scene.layout.heart_long_axis;
  heart.lateral = scene.layout.heart_lateral;
  const Real s = scene.patient.heart_scale;
  heart.lv_length *= s, heart.lv_radius *= s, heart.rv_length *= s, heart.rv_radius *= s;
  heart.rv_offset *= s;
  return heart;
}

// The lowest point of the tissue free to move, at rest (unit: m).
Real lowest_free_particle_y(const tissue::TissueWorld& w) {
  const physics::Particles& P = w.state.particles;
  Real lowest = std::numeric_limits<Real>::infinity();
  for (std::size_t i = 0; i < P.size(); ++i)
    if (P.inverse_mass[i] > 0) lowest = std::min(lowest, P.position[i].y());
  return std::isfinite(lowest) ? lowest : Real(0);
}

}  // namespace

ThoraxScene make_thorax_scene(const ThoraxSceneParams& params) {
  ThoraxScene scene;
  scene.setup_notes = params.file_notes;
  scene.patient = vary_anatomy(params.anatomy);
  scene.layout = layout_thorax(scene.patient, params.heart.long_axis, params.heart.lateral);
  scene.patch = tissue::make_thoracic_patch(lay_out_patch(params, scene.patient, scene.layout));
  scene.layout.cavity_floor_y =
      lowest_free_particle_y(scene.patch.world) - scene.patient.cavity_floor_gap;
  tissue::HeartModel heart_model;
  if (params.heart_series.phase_files.empty()) {
    heart_model = tissue::make_procedural_heart(builtin_heart(params, scene));
  } else {
    heart_model = load_heart_series(params.heart_series, &scene.setup_notes);
    if (params.heart_series.placement == kAutoPlacement) {
      scene.setup_notes.push_back(place_heart_automatically(
          heart_model, scene.layout, tissue::make_procedural_heart(builtin_heart(params, scene))));
    }
  }
  scene.heart = tissue::make_heart_field(heart_model, params.playback);
  scene.skeleton = make_chest_skeleton(scene.patient);
  tissue::TissueWorld& w = scene.patch.world;
  // Deep tissues anchored to the heart's motion: the vessel and the fat around it, and the
  // fascia (whose fixed perimeter is its anchor). Not the chest wall: bone does not beat (run's
  // chest_wall_motion_max_m reports it).
  tissue::add_heart_anchors(scene.heart, w, {scene.patch.ima, scene.patch.fascia},
                            {scene.patch.ima_fat});
  tissue::advance_heart(scene.heart, w, w.state.time);
  if (params.heart_series.phase_files.empty()) {
    check_heart_placement(scene.heart, w, scene.layout, kBuiltinHeartOverlapTolerance,
                          "change anatomy.heart_offset_m or the heart's size");
  } else {
    check_heart_placement(scene.heart, w, scene.layout, kLoadedHeartOverlapTolerance,
                          "move the phase meshes with heart.mesh_translation_m, or set "
                          "heart.placement = \"auto\"");
  }
  // Tissue generated at rest may start inside the heart: put it out once, with a wide search.
  tissue::collide_with_heart(scene.heart, w.state.particles, w.state.particles.position,
                             Real(0.03));
  tissue::finish_tissue_step(w);
  scene.ports = params.ports;
  aim_ports(scene.ports, params.port_target);
  if (params.fascia_solver == kImplicitFasciaSolver) {
    const physics::MembraneMaterial& m = *params.patch.fascia.object.membrane;
    // The masses are the particles' (eq. 5): the law's density is not read.
    use_implicit_fascia(scene, {m.youngs_modulus, params.fascia_linear_modulus,
                                params.fascia_toe_strain, m.thickness, Real(0)});
  }
  if (params.vessel_solver == kImplicitFasciaSolver) use_implicit_vessel(scene);
  return scene;
}

void prepare_thorax_step(ThoraxScene& scene, physics::StepProfile& profile,
                         const physics::Executor& exec) {
  Stopwatch clock;
  tissue::TissueWorld& w = scene.patch.world;
  const Real dt = w.model.solver.dt;
  // The heart at the end of this step's interval drives the boundary for the step.
  tissue::advance_heart(scene.heart, w, w.state.time + double(dt));
  profile[physics::Stage::heart] += clock.lap();
  physics::ContactSet& contacts = w.state.contacts;
  contacts.clear();
  tissue::gather_heart_contacts(scene.heart, w.state.particles, dt, scene.contact, contacts, exec);
  tissue::gather_wall_and_floor_contacts(scene.layout.wall, scene.layout.cavity_floor_y,
                                         w.state.particles, dt, scene.contact, contacts, exec,
                                         scene.wall_and_floor_chunks);
  tissue::drop_held_rows(contacts, 0, w.held);
  profile[physics::Stage::contacts] += clock.lap();
}

physics::StepResult finish_thorax_step(ThoraxScene& scene, physics::Executor& exec) {
  tissue::TissueWorld& w = scene.patch.world;
  Stopwatch fascia_clock;
  // Nothing without an implicit fascia or vessel.
  const physics::StepResult fascia = step_scene_implicit(scene, exec);
  const double fascia_seconds = fascia_clock.lap();
  physics::StepResult r = fascia.ok() ? tissue::step_tissue_dynamics(w, exec) : fascia;
  release_scene_implicit(scene);
  r.profile[physics::Stage::solve] += fascia_seconds;
  if (!r.ok()) return r;
  Stopwatch clock;
  // Nothing should be inside the heart now; a particle that is was missed by the gathering.
  scene.missed_heart_contacts =
      tissue::collide_with_heart(scene.heart, w.state.particles, w.state.scratch.saved_position,
                                 exec, tissue::kHeartStepSearch, scene.heart.margin);
  scene.heart.last_contacts = heart_contacts(scene);
  r.profile[physics::Stage::contacts] += clock.lap();
  tissue::finish_tissue_step(w, exec);
  r.profile[physics::Stage::surfaces] += clock.lap();
  return r;
}

physics::StepResult step_thorax_scene(ThoraxScene& scene, physics::Executor& exec) {
  const physics::Executor::Awake awake(exec);  // as the session's step (surgical_session.cpp)
  physics::StepProfile before;
  prepare_thorax_step(scene, before, exec);
  physics::StepResult r = finish_thorax_step(scene, exec);
  r.profile += before;
  return r;
}

std::uint32_t heart_contacts(const ThoraxScene& scene) {
  return static_cast<std::uint32_t>(
      scene.patch.world.state.contacts.touching(tissue::kHeartContact, tissue::kHeartContact + 1));
}

}  // namespace imasim::scene
