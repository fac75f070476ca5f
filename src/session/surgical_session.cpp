#include "session/surgical_session.hpp"

#include <algorithm>
#include <limits>
#include <span>
#include <stdexcept>

#include "math/stopwatch.hpp"
#include "session/surface_stop_rows.hpp"
#include "session/surface_stops.hpp"
#include "tissue/tissue_step.hpp"

namespace imasim::session {
namespace {

using surgery::EventKind;
using surgery::Tissue;

// Tags of the instruments' contact rows: station k's are kToolContactTag + k.
constexpr std::uint32_t kToolContactTag = 16;

const scene::Port& find_port(const std::vector<scene::Port>& ports, const std::string& name) {
  for (const scene::Port& p : ports)
    if (p.name == name) return p;
  throw std::invalid_argument("surgical session: the scene has no '" + name + "' port");
}

surgery::InstrumentInput held_if_lost(const surgery::InstrumentInput& given) {
  surgery::InstrumentInput in = given;
  if (!in.device_lost) return in;
  // A hand pose moves nothing while clutched (the arm re-anchors when it returns); a tool pose
  // is not followed.
  in.clutch = true;
  if (in.source == surgery::PoseSource::tool) in.source = surgery::PoseSource::none;
  in.jaw = surgery::JawCommand::hold;
  in.pedal = surgery::PedalMode::off;
  in.power = 0;
  return in;
}

void update_pose(SurgicalSession& s, Station& st, const surgery::InstrumentInput& in) {
  st.previous_pose = st.pose;
  st.previous_pose.translation += st.carried;  // where the last step's solve left the tool
  st.carried = Vec3::Zero();                   // a step that fails carries nothing
  st.previous_controller = st.state.controller;
  if (in.device_lost) st.tool_registered = false;  // a returning tracker registers afresh
  switch (in.source) {
    case surgery::PoseSource::hand:
      surgery::update_arm(st.arm, in.pose, in.clutch, st.arm_state);
      break;
    case surgery::PoseSource::tool:
      if (s.params.tool_pose_clutch_registered) {
        // The arm's clutch at 1:1: the first tool pose registers as a clutch release does.
        surgery::ArmParams one_to_one = st.arm;
        one_to_one.motion_scale = 1;
        if (!st.tool_registered || st.source != surgery::PoseSource::tool)
          st.arm_state.clutched = true;
        st.tool_registered = true;
        surgery::update_arm(one_to_one, in.pose, in.clutch, st.arm_state);
        break;
      }
      st.arm_state.commanded = in.pose;
      st.arm_state.tool = surgery::constrain_to_port(st.arm, in.pose);
      break;
    case surgery::PoseSource::none:
      break;
  }
  if (in.source != surgery::PoseSource::none) st.source = in.source;
  // The proxy: the device pose moved by the coupling's offset (tool_proxy.hpp).
  st.device = st.arm_state.tool;
  Pose proxy = st.device;
  proxy.translation += st.proxy.offset;
  st.state.controller = surgery::constrain_to_port(st.arm, proxy);
  surgery::integrate_jaws(st.instrument.jaws, in.jaw, s.scene.patch.world.model.solver.dt,
                          st.state);
  st.pose = surgery::world_pose(st.instrument, st.state);

  // The guard moves the proxy, not the hand's device: its offset takes the correction, within the
  // coupling's bound (beyond it the arm holds the device back, the bound's length behind).
  const Vec3 before = st.state.controller.translation;
  stop_at_surfaces(s, st);
  const Vec3 moved = st.state.controller.translation - before;
  if (moved.squaredNorm() > 0) {
    st.proxy.offset += moved;
    const Real length = st.proxy.offset.norm();
    const Real bound = s.params.proxy.max_offset;
    if (length > bound) {
      st.proxy.offset *= bound / length;
      st.device.translation = st.state.controller.translation - st.proxy.offset;
    }
  }
}

void build_geometry(SurgicalSession& s, Station& st, bool holding) {
  const Real dt = s.scene.patch.world.model.solver.dt;
  if (st.instrument.kind == surgery::InstrumentKind::forceps) {
    surgery::make_tool_geometry(st.instrument, st.state, st.geometry);
    st.geometry.capsules.clear();
    // Open or closing jaws let tissue in between them (to be grasped); closed, they push it
    // like a blunt probe; what they hold stays between them.
    if (!st.state.closed || holding) st.geometry.boxes.clear();
  } else {
    st.geometry.capsules.clear();
    st.geometry.boxes.clear();
    // In cut mode the energised electrode parts the tissue it meets (the cut, step 3) instead of
    // pushing it.
    if (st.pedal != surgery::PedalMode::cut) {
      const std::array<Vec3, 2> e = electrode(s);
      st.geometry.capsules.push_back({e[0], e[1], s.params.electrode_radius});
    }
  }
  // The shaft runs from the wrist, behind the hinge, back through the port.
  const Vec3 back = (st.arm.port - st.pose.translation).normalized();
  const Vec3 wrist = st.pose.translation + s.params.wrist_length * back;
  st.geometry.capsules.push_back(
      {wrist, wrist + st.instrument.shaft_length * back, st.instrument.shaft_radius});
  st.geometry.velocity = (st.pose.translation - st.previous_pose.translation) / dt;
}

void record_contacts(SurgicalSession& s, std::uint8_t index, Station& st, double time) {
  std::array<std::uint32_t, surgery::kTissueCount> count{};
  for (std::size_t o = 0; o < s.object_tissue.size() && o < 8; ++o)
    count[static_cast<std::size_t>(s.object_tissue[o])] += st.contact.per_object[o];
  if (st.blocked_by_heart) count[static_cast<std::size_t>(Tissue::heart)] += 1;
  if (st.blocked_by_wall) count[static_cast<std::size_t>(Tissue::chest_wall)] += 1;
  for (int t = 1; t < surgery::kTissueCount; ++t) {
    const bool now = count[t] > 0;
    if (now == st.touching[t]) continue;
    st.touching[t] = now;
    s.events.add(time, now ? EventKind::contact_begin : EventKind::contact_end, index,
                 static_cast<Tissue>(t), count[t], now ? st.contact.max_depth : Real(0));
  }
}

}  // namespace

Tissue tissue_of_particle(const SurgicalSession& s, std::uint32_t particle) {
  const auto& objects = s.scene.patch.world.state.particles.object;
  if (particle >= objects.size()) return Tissue::none;
  const std::size_t object = objects[particle];
  return object < s.object_tissue.size() ? s.object_tissue[object] : Tissue::none;
}

geometry::TriangleMesh static_heart_mesh(const SurgicalSession& s) {
  geometry::TriangleMesh m;
  m.vertices = s.scene.heart.reference;
  m.triangles = s.scene.heart.model.topology.triangles;
  return m;
}

std::array<Vec3, 2> electrode(const SurgicalSession& s) {
  const Pose& p = s.stations[1].pose;
  return {p.translation, p.translation + s.params.cautery.electrode_length * p.rotation.col(2)};
}

SurgicalSession make_surgical_session(const scene::ThoraxSceneParams& scene_params,
                                      const SessionParams& params) {
  SurgicalSession s;
  s.params = params;
  s.scene = scene::make_thorax_scene(scene_params);
  tissue::TissueWorld& w = s.scene.patch.world;
  const tissue::ThoracicPatch& patch = s.scene.patch;
  // The forceps' proxy is body 0: held tissue pulls it inside the solve.
  s.grasper = surgery::make_grasper(w, params.grasp, 0);

  s.object_tissue.assign(w.model.objects.size(), Tissue::none);
  s.object_tissue[w.meshes[patch.wall].object] = Tissue::chest_wall;
  s.object_tissue[w.meshes[patch.fascia].object] = Tissue::fascia;
  s.object_tissue[w.meshes[patch.ima].object] = Tissue::ima;
  std::vector<physics::ObjectId> heatable = {w.meshes[patch.fascia].object,
                                             w.meshes[patch.ima].object};
  for (const tissue::StrandSet& set : w.strands) {
    s.object_tissue[set.object] = Tissue::fat;
    heatable.push_back(set.object);
  }
  s.cautery = surgery::make_cautery_state(w, params.cautery, heatable, w.meshes[patch.ima].object);
  s.cutter = surgery::make_fascia_cutter(patch.fascia);
  tissue::finish_setup(w);

  // The scene file's console settings: the hands' motion scaling, the proxy's coupling, and per
  // tissue eq. 17's k_d and eq. 18's mu (in the force model's order of kForceTissueNames).
  const scene::ConsoleSettings& console = scene_params.console;
  s.params.tool_pose_clutch_registered = console.tool_registration == "clutch";
  const Tissue force_order[5] = {Tissue::fascia, Tissue::fat, Tissue::ima, Tissue::heart,
                                 Tissue::chest_wall};
  for (std::size_t k = 0; k < 5; ++k) {
    s.params.proxy.stiffness[std::size_t(force_order[k])] = console.force[k].stiffness;
    s.params.proxy.friction[std::size_t(force_order[k])] = console.force[k].friction;
  }
  s.params.proxy.coupling_stiffness = console.proxy_stiffness;
  s.params.proxy.coupling_damping = console.proxy_damping;
  const char* names[2] = {"left_instrument", "right_instrument"};
  for (int k = 0; k < 2; ++k) {
    Station& st = s.stations[k];
    st.instrument.kind =
        k == 0 ? surgery::InstrumentKind::forceps : surgery::InstrumentKind::cautery_hook;
    const scene::Port& port = find_port(s.scene.ports, names[k]);
    st.arm.port = port.position;
    st.arm.motion_scale = console.motion_scale;
    const Vec3 target = scene_params.port_target;
    Pose start;
    start.translation = port.position + params.start_fraction * (target - port.position);
    start.rotation = surgery::frame_along((target - port.position).normalized());
    st.arm_state = surgery::make_arm_state(st.arm, start, Pose{});
    st.state.controller = st.device = st.arm_state.tool;
    st.state.jaw_angle = 0;
    st.state.closed = true;
    st.pose = st.previous_pose = surgery::world_pose(st.instrument, st.state);
    st.geometry.capsules.reserve(4);
    st.geometry.boxes.reserve(4);
  }
  s.contacts.reserve(w.state.particles.size());
  w.state.proxies.assign(2, physics::ProxyBody{});  // the stations' proxies, prepared each step
  s.camera_port = find_port(s.scene.ports, "camera");
  s.camera =
      surgery::endoscope_view(s.camera_port.position, s.camera_port.direction, params.endoscope);
  return s;
}

SessionInput sample_script(const surgery::InputScript& script, double t) {
  SessionInput in;
  in.left = surgery::sample_instrument(script.left, t);
  in.right = surgery::sample_instrument(script.right, t);
  in.camera = surgery::sample_camera(script.camera, t);
  return in;
}

physics::StepResult step_session(SurgicalSession& s, const SessionInput& input,
                                 physics::Executor& exec) {
  // The step's loops on several threads are parted by serial stretches (the instruments, the
  // heart's advance, the session's bookkeeping) longer than a worker waits awake.
  const physics::Executor::Awake awake(exec);
  tissue::TissueWorld& w = s.scene.patch.world;
  const Real dt = w.model.solver.dt;
  const double time = w.state.time;  // events are stamped with the step's start
  Stopwatch clock;
  physics::StepProfile profile;

  // 0. An instrument whose device is gone holds still with no energy (the live console releases
  // it already; a stream or a front end that did not is held here all the same).
  const std::array<surgery::InstrumentInput, 2> in = {held_if_lost(input.left),
                                                      held_if_lost(input.right)};
  for (std::uint8_t k = 0; k < 2; ++k) {
    Station& st = s.stations[k];
    if (in[k].device_lost == st.device_lost) continue;
    st.device_lost = in[k].device_lost;
    s.events.add(time, st.device_lost ? EventKind::device_lost : EventKind::device_restored, k,
                 Tissue::none);
  }

  // 1. Instruments and camera.
  update_pose(s, s.stations[0], in[0]);
  update_pose(s, s.stations[1], in[1]);
  surgery::EndoscopeParams camera = s.params.endoscope;
  camera.optics_angle = input.camera.optics;
  if (input.camera.insertion) camera.insertion = *input.camera.insertion;
  if (input.camera.roll) camera.roll = *input.camera.roll;
  s.camera = surgery::endoscope_view(s.camera_port.position, s.camera_port.direction, camera);

  // 2. Grasping with the forceps.
  Station& forceps = s.stations[0];
  const std::size_t held_before = s.grasper.held.size();
  surgery::update_grasp(w, s.params.grasp, forceps.instrument, forceps.state, s.grasper);
  const std::size_t held = s.grasper.held.size();
  if (held > 0 && held_before == 0) {
    s.events.add(time, EventKind::grasp, 0, Tissue::none, static_cast<std::uint32_t>(held));
  }
  if (held == 0 && held_before > 0) {
    s.events.add(time, EventKind::release, 0, Tissue::none,
                 static_cast<std::uint32_t>(held_before));
  }

  // 3. Electrocautery.
  bool freed = held == 0 && held_before > 0;  // whether a piece of fascia may have come free
  Station& hook = s.stations[1];
  const surgery::PedalMode pedal = in[1].pedal;
  if (pedal != hook.pedal) {
    if (hook.pedal != surgery::PedalMode::off) {
      s.events.add(time, EventKind::cautery_off, 1, Tissue::none);
    }
    if (pedal != surgery::PedalMode::off) {
      s.events.add(time, EventKind::cautery_on, 1, Tissue::none, 0, in[1].power);
    }
    hook.pedal = pedal;
  }
  surgery::CauteryParams cautery = s.params.cautery;
  cautery.power = in[1].power;
  hook.power_w = pedal == surgery::PedalMode::off ? Real(0) : cautery.power;
  const std::array<Vec3, 2> e = electrode(s);
  const surgery::CauteryStep heat =
      surgery::apply_cautery(w, cautery, pedal, e[0], e[1], dt, s.cautery);
  s.cautery_energy += heat.energy;
  if (heat.injured > 0) {
    s.events.add(time, EventKind::injury, 1, Tissue::ima, heat.injured, heat.max_ima_rise);
  }
  profile[physics::Stage::instruments] += clock.lap();
  if (pedal == surgery::PedalMode::cut && heat.touching > 0) {
    const Pose& before = hook.previous_pose;
    const Vec3 a0 = before.translation;
    const Vec3 b0 = a0 + cautery.electrode_length * before.rotation.col(2);
    const surgery::FasciaCutResult cut =
        surgery::cut_fascia(w, s.params.fascia_cut, {a0, b0 - a0, e[0] - a0}, s.cutter);
    if (cut.status != tissue::EditStatus::applied) {
      ++s.refused_cuts;
      s.events.add(time, EventKind::cut_refused, 1, Tissue::fascia);
    }
    if (cut.cut_edges > 0) {
      s.fascia_edges_cut += cut.cut_edges;
      s.events.add(time, EventKind::fascia_cut, 1, Tissue::fascia, cut.cut_edges);
    }
    // The cut's new vertices take their parents' temperature and heart anchors.
    surgery::inherit_cautery_state(w, cautery, s.cutter.mesh, cut.first_new_vertex,
                                   cut.new_vertices, s.cautery);
    tissue::anchor_new_vertices(s.scene.heart, w, s.cutter.mesh, cut.first_new_vertex,
                                cut.new_vertices);
    if (cut.edges_split + cut.vertices_copied > 0) {
      surgery::stiffen_coagulated(w, s.cautery);
      freed = true;
    }
  }
  if (pedal == surgery::PedalMode::cut) {
    // eq. 10-12 with p at the electrode's tip, where it meets the strands: a strand that crosses
    // the cutting square touches the live electrode, whether or not a particle of it (they are
    // about a millimetre apart) lies within the contact radius.
    s.strand_cuts.clear();
    const Pose tip{hook.pose.rotation, e[1]};
    const std::uint32_t strands =
        surgery::cut_strands(w, surgery::cut_plane(tip), s.params.strand_cut.width, s.strand_cuts);
    if (strands > 0) {
      s.strands_cut += strands;
      s.events.add(time, EventKind::strand_cut, 1, Tissue::fat, strands);
    }
  }

  // Pieces of fascia the cut or a release left free and small are vaporised.
  if (freed) {
    const surgery::FragmentRemoval gone =
        surgery::vaporise_free_fragments(w, s.params.fragments, s.cutter);
    if (gone.fragments > 0) {
      s.fragments_vaporised += gone.fragments;
      s.events.add(time, EventKind::fragment_vaporised, 1, Tissue::fascia, gone.triangles,
                   gone.area);
    }
  }

  // 4. The scene, with the instruments' contacts inside its solve (with the heart's and the
  // wall's): tissue is kept out of the shafts, the closed jaws and the electrode, with friction
  // against each contact point's own motion.
  // Coagulated tissue is stiffer in the implicit fascia's and vessel's steps too (its XPBD rows,
  // when it has them, took the stiffer material in apply_cautery).
  if (s.cautery.coagulated_count > 0) {
    scene::coagulate_scene_implicit(s.scene, s.cautery.coagulated,
                                    1 / s.params.cautery.coagulated_compliance_factor);
  }
  profile[physics::Stage::cutting] += clock.lap();
  scene::prepare_thorax_step(s.scene, profile, exec);
  clock.lap();
  // The heart and the wall stop the proxies inside the solve too: station k's rows are
  // [stop_first[k], stop_first[k + 1]).
  std::array<std::size_t, 3> stop_first{};
  w.state.body_stops.clear();
  for (std::uint8_t k = 0; k < 2; ++k) {
    Station& st = s.stations[k];
    build_geometry(s, st, k == 0 && held > 0);
    const std::size_t first = w.state.contacts.rows.size();
    surgery::gather_tool_contacts(w.state.particles, st.geometry, st.previous_pose, st.pose,
                                  s.params.contact, dt, kToolContactTag + k, w.state.contacts);
    gather_surface_stop_rows(s, st, k, w.state.body_stops);
    stop_first[k + 1] = w.state.body_stops.size();
    // Its rows are two-body contacts with its proxy, so the tissue stops it inside the solve.
    std::span<physics::ContactRow> rows(w.state.contacts.rows.data() + first,
                                        w.state.contacts.rows.size() - first);
    surgery::prepare_proxy_body(s.params.proxy, st.proxy, rows, k, w.state.particles.object.data(),
                                s.object_tissue.data(), s.object_tissue.size(), w.state.proxies[k]);
  }
  profile[physics::Stage::contacts] += clock.lap();
  physics::StepResult r = scene::finish_thorax_step(s.scene, exec);
  clock.lap();
  r.profile += profile;
  if (!r.ok()) return r;

  // 5. What touched; where the solve left each proxy; anything the gathering missed is put out
  // now (a warning).
  bool moved = false;
  for (std::uint8_t k = 0; k < 2; ++k) {
    Station& st = s.stations[k];
    st.contact =
        surgery::summarize_tool_contacts(w.state.particles, w.state.contacts, kToolContactTag + k);
    surgery::Tissue pressed = surgery::Tissue::none;
    const Vec3 normal_push = surgery::tissue_force_on_tool(
        w.state.contacts, w.state.particles.object.data(), s.object_tissue.data(),
        s.object_tissue.size(), kToolContactTag + k, dt, pressed);
    // The tool ended the step where the solve left its proxy: the local model's reference and
    // the next step's motion start there (the pose keeps the surfaces' stop until then).
    st.carried = w.state.proxies[k].carried();
    const surgery::Tissue stopped_by = note_surface_stop_rows(
        st,
        std::span<const physics::BodyStopRow>(w.state.body_stops.data() + stop_first[k],
                                              stop_first[k + 1] - stop_first[k]),
        st.carried, dt);
    Vec3 pull = Vec3::Zero();
    surgery::Tissue pulled_by = surgery::Tissue::none;
    if (k == 0 && !s.grasper.held.empty()) {
      // Held tissue pulls on the jaws: their attachments ride on the proxy and pulled it inside
      // the solve.
      pull = physics::held_pull_on_body(w.state.body_attachments, k, dt);
      pulled_by = tissue_of_particle(s, s.grasper.held.front().particle);
    }
    st.state.controller.translation += st.carried;
    surgery::translate_tool_geometry(st.geometry, st.carried);
    surgery::finish_proxy_step(w.state.proxies[k], dt, normal_push, pressed, pull, pulled_by,
                               stopped_by, st.proxy);
    const surgery::ContactSummary missed =
        surgery::resolve_tool_contacts(w.state.particles, w.state.scratch.saved_position,
                                       st.geometry, s.params.contact, dt, s.contacts);
    s.missed_tool_contacts += missed.inside;  // within the margin only is not a miss
    moved = moved || missed.count > 0;
    record_contacts(s, k, st, time);
  }
  r.profile[physics::Stage::contacts] += clock.lap();
  // 6. Strands stretched past tearing let go (a piece of fascia the cuts freed falls away with
  // their ends); divided and torn strands dissolve; surfaces again if contact moved tissue.
  s.strand_tears.clear();
  if (const std::uint32_t torn = tissue::tear_overstretched_strands(w, s.strand_tears); torn > 0) {
    s.strands_torn += torn;
    Real worst = 0;
    for (const tissue::StrandTear& t : s.strand_tears)
      worst = std::max(worst, t.stretch);
    s.events.add(time, EventKind::strand_torn, 1, Tissue::fat, torn, worst);
  }
  surgery::dissolve_cut_strands(w, s.params.strand_cut);
  r.profile[physics::Stage::cutting] += clock.lap();
  if (moved) tissue::finish_tissue_step(w, exec);
  r.profile[physics::Stage::surfaces] += clock.lap();
  s.profile.add(r.profile);
  return r;
}

}  // namespace imasim::session
