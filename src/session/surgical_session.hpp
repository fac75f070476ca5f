#pragma once
// A surgical session: the thorax scene with two robotic instruments at their ports (DeBakey
// forceps on the left, an electrocautery hook on the right), the endoscope at the camera port,
// and the event stream. One step, given the inputs of that step (a console, or a script):
//   1. each arm turns its input into the instrument's pose (hand through the arm's scaling and
//      clutch, or a tool pose), the jaws integrate their buttons (eq. 16), and the instrument
//      is held out of the heart and the chest wall (it stops at their surface);
//   2. the forceps grasp or release (and move what they hold);
//   3. the cautery heats what its electrode touches while the pedal is pressed; in cut mode it
//      cuts the fascia along the electrode's path (2.4.1) and the strands its plane crosses
//      (eq. 10-12);
//   4. the scene steps (heart, tissue), with the contacts of the heart, the chest wall and the
//      instruments' shafts, jaws and electrode inside its solve (with friction);
//   5. what touched is read back for the events; tissue the contacts missed is put out;
//   6. cut strands dissolve (eq. 13); the events of the step are recorded.
#include <array>
#include <cstdint>
#include <vector>

#include "scene/thorax_scene.hpp"
#include "session/probe_clearance.hpp"
#include "surgery/cautery.hpp"
#include "surgery/endoscope.hpp"
#include "surgery/events.hpp"
#include "surgery/fascia_cut.hpp"
#include "surgery/fascia_fragments.hpp"
#include "surgery/grasp.hpp"
#include "surgery/input_script.hpp"
#include "surgery/robotic_arm.hpp"
#include "surgery/strand_cut.hpp"
#include "surgery/tool_contact.hpp"
#include "surgery/tool_proxy.hpp"
#include "tissue/strand_tear.hpp"

namespace imasim::session {

struct SessionParams {
  surgery::GraspParams grasp;
  surgery::FasciaCutParams fascia_cut;
  surgery::FragmentParams fragments;
  surgery::StrandCutParams strand_cut;
  surgery::CauteryParams cautery;
  surgery::ContactParams contact;
  surgery::EndoscopeParams endoscope;
  Real electrode_radius = Real(0.0005);  // the hook's wire (unit: m)
  Real wrist_length = Real(0.008);       // hinge to the shaft's end (unit: m)
  Real tool_clearance = Real(0.0005);    // kept from the heart and the wall (unit: m)
  // Where each instrument starts: this fraction of the way from its port to the port target.
  Real start_fraction = Real(0.75);
  surgery::ProxyParams proxy;
  // Tool poses (a tracker on the instrument): placed where they say (false), or, registered at the
  // clutch (true), moving the tool by how far the tracker moved since the first pose or the last
  // clutch release, 1:1, with the tracker's turn (scene file: devices.tool_registration).
  bool tool_pose_clutch_registered = false;
};

// Where the heart or the chest wall stopped an instrument this step (the rows that stop its proxy
// inside the solve, else the god-object guard before it): the stopped probe point, a point of the
// plane it is stopped at (the surface plus the tools' clearance), the surface's outward normal
// there, and which one.
struct SurfaceStop {
  surgery::Tissue tissue = surgery::Tissue::none;  // none: not stopped
  Vec3 point = Vec3::Zero();                       // (unit: m)
  Vec3 plane = Vec3::Zero();                       // (unit: m)
  Vec3 normal = Vec3::UnitZ();
  Vec3 velocity = Vec3::Zero();  // of the surface there: the heart's wall moves (unit: m/s)
  // The surface's push and friction on the tool over the last step, all its rows together; zero
  // when only the guard before the step stopped it (unit: N).
  Vec3 force = Vec3::Zero();
};

// One instrument at its port.
struct Station {
  surgery::InstrumentParams instrument;
  surgery::ArmParams arm;
  surgery::ArmState arm_state;
  surgery::InstrumentState state;
  Pose pose;           // T_world now
  Pose previous_pose;  // at the previous step
  Pose previous_controller;
  // The pose the hand or script asks for (T_controller before the proxy); the instrument
  // (`pose`) is the proxy: this plus proxy.offset, stopped by the heart and the wall.
  Pose device;
  surgery::ProxyState proxy;
  Vec3 carried = Vec3::Zero();  // how far the proxy moved inside the last step (unit: m)
  SurfaceStop stop;
  surgery::ToolGeometry geometry;
  surgery::ContactSummary contact;
  std::array<bool, surgery::kTissueCount> touching{};
  bool blocked_by_heart = false, blocked_by_wall = false;
  ProbeClearance heart_probes;  // a cache of the stops' heart searches (no effect on results)
  surgery::PedalMode pedal = surgery::PedalMode::off;
  Real power_w = 0;  // the cautery's power while the pedal is pressed (unit: W)
  surgery::PoseSource source = surgery::PoseSource::none;  // of the last pose given
  bool tool_registered = false;  // clutch registration: the tracker's anchor is set
  bool device_lost = false;      // its device is gone: held still, no energy (SessionInput)
};

struct SurgicalSession {
  scene::ThoraxScene scene;
  SessionParams params;
  std::array<Station, 2> stations;  // 0: forceps (left port), 1: cautery hook (right port)
  surgery::Grasper grasper;
  surgery::FasciaCutter cutter;
  surgery::CauteryState cautery;
  scene::Port camera_port;
  surgery::EndoscopeView camera;
  surgery::EventLog events;
  std::vector<surgery::Tissue> object_tissue;  // per physics object
  std::vector<surgery::ToolContact> contacts;  // scratch
  std::vector<surgery::StrandCut> strand_cuts;
  std::vector<tissue::StrandTear> strand_tears;
  // Totals for reports.
  std::uint64_t fascia_edges_cut = 0, strands_cut = 0;
  std::uint64_t strands_torn = 0;  // stretched past their tear_stretch (tissue/strand_tear.hpp)
  std::uint64_t fragments_vaporised = 0;  // small free pieces of fascia taken out after cuts
  // Warnings: tissue found inside an instrument after the step (the solve's contacts missed it),
  // cuts refused for want of spare vertices.
  std::uint64_t missed_tool_contacts = 0, refused_cuts = 0;
  Real cautery_energy = 0;  // (unit: J)
  // Where the successful steps' time went, per stage (the last step's is in its StepResult).
  physics::ProfileTotals profile;
};

struct SessionInput {
  surgery::InstrumentInput left, right;
  surgery::CameraInput camera;
};

// Throws what make_thorax_scene throws, and std::invalid_argument for bad parameters or a scene
// without its camera and instrument ports.
SurgicalSession make_surgical_session(const scene::ThoraxSceneParams& scene_params,
                                      const SessionParams& params);

physics::StepResult step_session(SurgicalSession& session, const SessionInput& input,
                                 physics::Executor& exec);

// The inputs of a script at time t.
SessionInput sample_script(const surgery::InputScript& script, double t);

// The cautery electrode's ends (world): from the hinge along f for the electrode's length.
std::array<Vec3, 2> electrode(const SurgicalSession& session);

// The heart at its static phase (the paper's 70 % reference), which eq. 20 takes as the heart's
// side of the IMA.
geometry::TriangleMesh static_heart_mesh(const SurgicalSession& session);

}  // namespace imasim::session
