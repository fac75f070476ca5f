#include "scene/scene_keys.hpp"

#include <array>
#include <limits>
#include <numbers>

#include "scene/solver_budget.hpp"

namespace imasim::scene {

namespace {

using Params = ThoraxSceneParams;
// Bounds on each component of a vector key (a set-up with a coordinate of 1e300 loops for
// ever; one of 1e200 fails deep inside the layout with a message naming no key):
// positions in the room frame: the thorax spans well under a metre about the origin;
constexpr double kRoom = 1;  // (unit: m)
// the heart's centre from the IMA's mid-course centre: the cavity is about 30 cm across;
constexpr double kHeartReach = 0.25;  // (unit: m)
// a mesh's move after scaling: a scanner's coordinates reach about a metre from its origin;
constexpr double kMeshReach = 10;  // (unit: m)
// rotation vectors (axis * angle): a larger component is degrees written as radians;
constexpr double kTurn = 2 * std::numbers::pi;  // (unit: rad)
// directions: only their direction counts; the bound keeps products of them finite.
constexpr double kDirection = 1e3;
// heart.placement (scene/heart_placement.hpp).
constexpr std::array<std::string_view, 2> kPlacementChoices = {kFilePlacement, kAutoPlacement};

// fascia.solver and vessel.solver (ThoraxSceneParams::fascia_solver, vessel_solver).
constexpr std::array<std::string_view, 2> kFasciaSolvers = {kXpbdFasciaSolver,
                                                            kImplicitFasciaSolver};

// Keys of the two strand sets differ only in the set they address.
#define IMASIM_STRAND_KEYS(table, member)                                                         \
  SceneKey{table ".strands_per_face",                                                             \
           RealRef([](Params& p) { return &p.patch.member.generation.strands_per_face; }), 0, 20, \
           "sigma: strands per facing face; the fraction is the chance of one more (2.3.4)"},     \
      SceneKey{table ".segments",                                                                 \
               CountRef([](Params& p) { return &p.patch.member.generation.segments; }), 1, 64,    \
               "n: segments per strand (2.3.4)"},                                                 \
      SceneKey{table ".max_angle_rad",                                                            \
               RealRef([](Params& p) { return &p.patch.member.generation.max_angle; }), 0, 1.5,   \
               "theta: largest deviation of a strand from its face normal"},                      \
      SceneKey{table ".seed", SeedRef([](Params& p) { return &p.patch.member.generation.seed; }), \
               0, 9e18, "random seed of the strand generator"},                                   \
      SceneKey{table ".diameter_m", RealRef([](Params& p) { return &p.patch.member.diameter; }),  \
               1e-5, 0.02, "drawn diameter of a strand particle"},                                \
      SceneKey{table ".total_mass_kg",                                                            \
               RealRef([](Params& p) { return &p.patch.member.total_mass; }), 1e-6, 10,           \
               "mass spread over the interior strand particles (eq. 5)"},                         \
      SceneKey{table ".youngs_modulus_pa",                                                        \
               RealRef([](Params& p) { return &p.patch.member.youngs_modulus; }), 10, 1e8,        \
               "E of the connective tissue; a strand carries its face's share (fat: 3.25 kPa)"},  \
      SceneKey{table ".linear_damping",                                                           \
               RealRef([](Params& p) { return &p.patch.member.linear_damping; }), 0, 0.99,        \
               "k_l of eq. 4: share of velocity removed per 5 ms"},                               \
      SceneKey{table ".tear_stretch",                                                             \
               RealRef([](Params& p) { return &p.patch.member.tear_stretch; }), 1.01, 1e3,        \
               "a strand tears with its ends this many times their rest distance apart"},         \
      SceneKey{table ".resists_compression",                                                      \
               BoolRef([](Params& p) { return &p.patch.member.resists_compression; }), 0, 0,      \
               "the fat holds what it binds and pushes back (its strands as columns)"},           \
      SceneKey{table ".xsph_coefficient",                                                         \
               RealRef([](Params& p) { return &p.patch.member.xsph_coefficient; }), 0, 1,         \
               "share of the neighbours' mean velocity taken per step (XSPH)"},                   \
      SceneKey {                                                                                  \
    table ".xsph_radius_m", RealRef([](Params& p) { return &p.patch.member.xsph_radius; }), 1e-5, \
        0.1, "XSPH neighbourhood radius at rest"                                                  \
  }

// The force model's keys of one tissue (eq. 17-19; docs/haptics.md), table force_<tissue>.
#define IMASIM_FORCE_KEYS(table, i)                                                                \
  SceneKey{table ".stiffness_n_per_m",                                                             \
           RealRef([](Params& p) { return &p.console.force[i].stiffness; }), 1, 1e5,               \
           "k_d of eq. 17: the stiffness the hand feels the tissue at"},                           \
      SceneKey{table ".damping_n_s_per_m",                                                         \
               RealRef([](Params& p) { return &p.console.force[i].damping; }), 0.01, 1e3,          \
               "c_d of eq. 17"},                                                                   \
      SceneKey{table ".friction", RealRef([](Params& p) { return &p.console.force[i].friction; }), \
               0, 2, "mu of eq. 18, also the instruments' contact friction"},                      \
      SceneKey{table ".cutting_resistance_n_s_per_m",                                              \
               RealRef([](Params& p) { return &p.console.force[i].cutting_resistance; }), 0, 1e3,  \
               "k_c of eq. 18"},                                                                   \
      SceneKey{table ".cut_thermal_n_per_w",                                                       \
               RealRef([](Params& p) { return &p.console.force[i].cut_coefficient; }), 0, 1,       \
               "k_t of eq. 19 in cut mode"},                                                       \
      SceneKey{table ".cut_thermal_decay_per_m",                                                   \
               RealRef([](Params& p) { return &p.console.force[i].cut_decay; }), 0, 1e5,           \
               "alpha of eq. 19 in cut mode"},                                                     \
      SceneKey{table ".coag_thermal_n_per_w",                                                      \
               RealRef([](Params& p) { return &p.console.force[i].coag_coefficient; }), 0, 1,      \
               "k_t of eq. 19 in coagulation mode"},                                               \
      SceneKey {                                                                                   \
    table ".coag_thermal_decay_per_m",                                                             \
        RealRef([](Params& p) { return &p.console.force[i].coag_decay; }), 0, 1e5,                 \
        "alpha of eq. 19 in coagulation mode"                                                      \
  }

#define IMASIM_NAME_KEY(key, member, doc)                                               \
  SceneKey {                                                                            \
    "devices." key, NameKeyRef{[](Params& p) { return &p.console.member; }}, 1, 20, doc \
  }

#define IMASIM_BUTTON_KEY(key, member, doc)                                            \
  SceneKey {                                                                           \
    "devices." key, ChoiceRef([](Params& p) { return &p.console.member; }), 0, 0, doc, \
        kGamepadButtonNames                                                            \
  }

const SceneKey kKeys[] = {
    {"anatomy.patient_seed", SeedRef([](Params& p) { return &p.anatomy.patient_seed; }), 0, 9e18,
     "0 = the typical patient below; else a virtual patient varied about it (docs/anatomy.md)"},
    {"anatomy.sternum_position_m", Vec3Ref([](Params& p) { return &p.anatomy.sternum_position; }),
     -kRoom, kRoom, "midline of the sternum's inner surface at the IMA's cranial end"},
    {"anatomy.sternum_width_m", RealRef([](Params& p) { return &p.anatomy.sternum_width; }), 0.015,
     0.06, "sternum width (typical 25-40 mm)"},
    {"anatomy.ima_lateral_offset_m",
     RealRef([](Params& p) { return &p.anatomy.ima_lateral_offset; }), 0.01, 0.05,
     "left IMA from the sternal midline (typical 20-30 mm)"},
    {"anatomy.ima_lateral_drift_m", RealRef([](Params& p) { return &p.anatomy.ima_lateral_drift; }),
     -0.02, 0.03, "further lateral offset at the caudal end of the course"},
    {"anatomy.ima_depth_m", RealRef([](Params& p) { return &p.anatomy.ima_depth; }), 0.002, 0.015,
     "IMA centre under the chest wall's inner surface"},
    {"anatomy.ima_course_length_m", RealRef([](Params& p) { return &p.anatomy.ima_course_length; }),
     0.15, 0.3, "simulated IMA course, >= 15 cm so a 10 cm segment can be harvested"},
    {"anatomy.chest_wall_radius_m", RealRef([](Params& p) { return &p.anatomy.chest_wall_radius; }),
     0.06, 0.5, "transverse curvature radius of the chest wall's inner surface"},
    {"anatomy.fat_thickness_m", RealRef([](Params& p) { return &p.anatomy.fat_thickness; }), 0.004,
     0.03, "chest wall to fascia"},
    {"anatomy.fascia_width_m", RealRef([](Params& p) { return &p.anatomy.fascia_width; }), 0.01,
     0.1, "fascia extent across the IMA (w of 2.3.1)"},
    {"anatomy.fascia_length_m", RealRef([](Params& p) { return &p.anatomy.fascia_length; }), 0.05,
     0.3, "fascia extent along the IMA (h of 2.3.1)"},
    {"anatomy.rib_spacing_m", RealRef([](Params& p) { return &p.anatomy.rib_spacing; }), 0.012,
     0.05, "cranio-caudal pitch of the ribs (display)"},
    {"anatomy.heart_scale", RealRef([](Params& p) { return &p.anatomy.heart_scale; }), 0.5, 2,
     "on the procedural heart's lengths and radii"},
    {"anatomy.heart_offset_m", Vec3Ref([](Params& p) { return &p.anatomy.heart_offset; }),
     -kHeartReach, kHeartReach, "LV centre from the IMA's mid-course centre"},
    {"anatomy.heart_tilt_rad", Vec3Ref([](Params& p) { return &p.anatomy.heart_tilt; }), -kTurn,
     kTurn, "axis * angle turning the heart's orientation"},
    {"anatomy.cavity_floor_gap_m", RealRef([](Params& p) { return &p.anatomy.cavity_floor_gap; }),
     0.005, 0.3,
     "the cavity's floor (collapsed lung, pericardium) below the lowest tissue at rest: freed "
     "tissue rests on it"},

    {"solver.dt_s", RealRef([](Params& p) { return &p.patch.solver.dt; }), 1e-5, 0.1,
     "step; the paper's 5 ms (2.3.1)"},
    {"solver.substeps", CountRef([](Params& p) { return &p.patch.solver.substeps; }), 1,
     double(kMaxSweepsPerStep), "substeps per 5 ms step: the solver's accuracy (docs/physics.md)"},
    {"solver.iterations", CountRef([](Params& p) { return &p.patch.solver.iterations; }), 1,
     double(kMaxSweepsPerStep),
     "projection sweeps per substep (the paper: 5 sweeps of one 5 ms step)"},
    {"solver.coarse_stride", CountRef([](Params& p) { return &p.patch.solver.coarse_stride; }), 1,
     1000, "the fat strands step every this many substeps (gcd with substeps)"},
    {"solver.bending_stride", CountRef([](Params& p) { return &p.patch.solver.bending_stride; }), 1,
     1000, "the fascia's bending rows are projected every this many substeps (gcd with substeps)"},
    {"solver.stretch_sweeps", CountRef([](Params& p) { return &p.patch.solver.stretch_sweeps; }), 1,
     4, "sweeps of the fine stretch rows and contacts per iteration (docs/physics.md)"},
    {"solver.coarse_sweeps", CountRef([](Params& p) { return &p.patch.solver.coarse_sweeps; }), 1,
     4, "sweeps of the coarse objects' rows (strands, IMA) per coarse substep (docs/physics.md)"},
    {"solver.max_speed_m_per_s", RealRef([](Params& p) { return &p.patch.solver.max_speed; }), 1e-6,
     1e6, "divergence guard: a faster particle fails the step"},
    {"solver.push_out_speed_m_per_s",
     RealRef([](Params& p) { return &p.patch.solver.push_out_speed; }), 1e-4, 100,
     "how fast tissue found inside a surface at a step's start is pushed out (docs/physics.md)"},

    {"heart.beating", BoolRef([](Params& p) { return &p.playback.beating; }), 0, 0,
     "false = the paper's static group"},
    {"heart.heart_rate_bpm", RealRef([](Params& p) { return &p.playback.heart_rate_bpm; }), 20, 250,
     "heart rate"},
    {"heart.static_phase", RealRef([](Params& p) { return &p.playback.static_phase; }), 0, 1,
     "cycle fraction of the static heart and of the beating heart's start (paper: 70 %)"},
    {"heart.phases", CountRef([](Params& p) { return &p.heart.phases; }), 3, 200,
     "keyframes per cycle (paper: 11)"},
    {"heart.ejection_fraction", RealRef([](Params& p) { return &p.heart.ejection_fraction; }), 0.05,
     0.95, "(EDV - ESV) / EDV"},
    {"heart.systole_fraction", RealRef([](Params& p) { return &p.heart.systole_fraction; }), 0.05,
     0.95, "share of the cycle spent ejecting"},
    {"heart.longitudinal_shortening",
     RealRef([](Params& p) { return &p.heart.longitudinal_shortening; }), 0, 0.5,
     "base-apex shortening at end-systole"},
    {"heart.twist_rad", RealRef([](Params& p) { return &p.heart.twist; }), -1.5, 1.5,
     "apex rotation against the base at end-systole"},
    {"heart.long_axis", Vec3Ref([](Params& p) { return &p.heart.long_axis; }), -kDirection,
     kDirection, "direction base -> apex"},
    {"heart.lateral", Vec3Ref([](Params& p) { return &p.heart.lateral; }), -kDirection, kDirection,
     "direction towards the right ventricle"},
    {"heart.lv_length_m", RealRef([](Params& p) { return &p.heart.lv_length; }), 0.01, 0.3,
     "LV base-apex length at end-diastole"},
    {"heart.lv_radius_m", RealRef([](Params& p) { return &p.heart.lv_radius; }), 0.005, 0.1,
     "LV radius at end-diastole"},
    {"heart.rv_length_m", RealRef([](Params& p) { return &p.heart.rv_length; }), 0.01, 0.3,
     "RV base-apex length at end-diastole"},
    {"heart.rv_radius_m", RealRef([](Params& p) { return &p.heart.rv_radius; }), 0.005, 0.1,
     "RV radius at end-diastole"},
    {"heart.rv_offset_m", RealRef([](Params& p) { return &p.heart.rv_offset; }), 0, 0.1,
     "RV centre from the LV centre, along lateral"},
    {"heart.phase_files", PathListRef([](Params& p) { return &p.heart_series.phase_files; }), 0, 0,
     "closed surface meshes (OBJ/STL/PLY/glTF), one per phase in cycle order, one topology; "
     "relative to this file; empty = the procedural heart"},
    {"heart.placement", ChoiceRef([](Params& p) { return &p.heart_series.placement; }), 0, 0,
     "\"file\": the phase meshes where mesh_scale/rotation/translation put them; \"auto\": "
     "placed from their shape (long axis, apex, centre) under the IMA where the built-in heart "
     "sits, the rotation and translation ignored",
     kPlacementChoices},
    {"heart.mesh_scale", RealRef([](Params& p) { return &p.heart_series.transform.scale; }), 1e-6,
     1e3, "phase files' units to m (0.001: millimetres)"},
    {"heart.mesh_rotation_rad",
     Vec3Ref([](Params& p) { return &p.heart_series.transform.rotation; }), -kTurn, kTurn,
     "axis * angle turning the phase meshes"},
    {"heart.mesh_translation_m",
     Vec3Ref([](Params& p) { return &p.heart_series.transform.translation; }), -kMeshReach,
     kMeshReach, "moves the phase meshes after scale and rotation"},
    {"heart.rings", CountRef([](Params& p) { return &p.heart.rings; }), 3, 128,
     "surface rings per ventricle"},
    {"heart.segments", CountRef([](Params& p) { return &p.heart.segments; }), 3, 256,
     "surface segments per ring"},

    {"chest_wall.nu", CountRef([](Params& p) { return &p.patch.wall.nu; }), 2, 1024,
     "vertices around"},
    {"chest_wall.nv", CountRef([](Params& p) { return &p.patch.wall.nv; }), 2, 1024,
     "vertices along"},

    {"fascia.nx", CountRef([](Params& p) { return &p.patch.fascia.nx; }), 3, 1024,
     "vertices across"},
    {"fascia.ny", CountRef([](Params& p) { return &p.patch.fascia.ny; }), 3, 1024,
     "vertices along"},
    {"fascia.total_mass_kg", RealRef([](Params& p) { return &p.patch.fascia.object.total_mass; }),
     1e-6, 10, "M_total of eq. 5"},
    {"fascia.linear_damping",
     RealRef([](Params& p) { return &p.patch.fascia.object.linear_damping; }), 0, 0.99,
     "k_l of eq. 4: share of velocity removed per 5 ms (paper: 0.03)"},
    {"fascia.angular_damping",
     RealRef([](Params& p) { return &p.patch.fascia.object.angular_damping; }), 0, 1,
     "k_c of eq. 4: share of the non-rigid velocity removed per 5 ms (paper: 0.01)"},
    {"fascia.youngs_modulus_pa",
     RealRef([](Params& p) { return &p.patch.fascia.object.membrane->youngs_modulus; }), 1e3, 1e9,
     "E of the fascia in tension (superficial fascia: 2.65 MPa)"},
    {"fascia.solver", ChoiceRef([](Params& p) { return &p.fascia_solver; }), 0, 0,
     "\"xpbd\": the fascia's rows in the step's sweeps at youngs_modulus_pa at every strain; "
     "\"implicit\": a Newton solve of the step, youngs_modulus_pa in the toe and "
     "linear_modulus_pa past toe_strain (docs/physics.md)",
     kFasciaSolvers},
    {"fascia.linear_modulus_pa", RealRef([](Params& p) { return &p.fascia_linear_modulus; }), 1e3,
     1e9,
     "E of the fascia past its toe strain (superficial fascia's linear region: 2.65 MPa); "
     "solver = \"implicit\" only"},
    {"fascia.toe_strain", RealRef([](Params& p) { return &p.fascia_toe_strain; }), 1e-3, 0.5,
     "strain where the fascia's collagen is recruited (toe to linear region); solver = "
     "\"implicit\" only"},
    {"fascia.thickness_m",
     RealRef([](Params& p) { return &p.patch.fascia.object.membrane->thickness; }), 1e-5, 0.01,
     "fascia thickness t (stretch stiffness E t)"},
    {"fascia.bending_stiffness_n_m",
     RealRef([](Params& p) { return &p.patch.fascia.object.membrane->bending_stiffness; }), 0, 1,
     "D; 0 = the plate's E t^3 / (12 (1 - nu^2))"},

    {"vessel.radius_m", RealRef([](Params& p) { return &p.patch.vessel.radius; }), 2e-4, 0.01,
     "IMA radius (about 1-1.5 mm)"},
    {"vessel.coarse_segments", CountRef([](Params& p) { return &p.patch.vessel.coarse_segments; }),
     3, 64, "simulated tube: vertices per ring"},
    {"vessel.coarse_rings", CountRef([](Params& p) { return &p.patch.vessel.coarse_rings; }), 2,
     4096, "simulated tube: rings"},
    {"vessel.fine_segments", CountRef([](Params& p) { return &p.patch.vessel.fine_segments; }), 3,
     256, "visual tube: vertices per ring"},
    {"vessel.fine_rings", CountRef([](Params& p) { return &p.patch.vessel.fine_rings; }), 2, 16384,
     "visual tube: rings"},
    {"vessel.coarse", BoolRef([](Params& p) { return &p.patch.vessel.object.coarse; }), 0, 0,
     "solved in the coarse band (solver.coarse_stride, coarse_sweeps); false: every substep"},
    {"vessel.solver", ChoiceRef([](Params& p) { return &p.vessel_solver; }), 0, 0,
     "\"xpbd\": the vessel's rows in the step's sweeps; \"implicit\": a Newton solve of the "
     "step with the same rows' energy (docs/physics.md)",
     kFasciaSolvers},
    {"vessel.total_mass_kg", RealRef([](Params& p) { return &p.patch.vessel.object.total_mass; }),
     1e-6, 10, "M_total of eq. 5"},
    {"vessel.youngs_modulus_pa",
     RealRef([](Params& p) { return &p.patch.vessel.object.membrane->youngs_modulus; }), 1e3, 1e9,
     "E of the IMA's wall (about 1.5 MPa)"},
    {"vessel.wall_thickness_m",
     RealRef([](Params& p) { return &p.patch.vessel.object.membrane->thickness; }), 1e-5, 0.005,
     "IMA wall thickness (about 0.35 mm); stretch E t, bending E t^3 / (12 (1 - nu^2))"},

    IMASIM_STRAND_KEYS("ima_fat", ima_fat),
    IMASIM_STRAND_KEYS("fascia_fat", fascia_fat),

    {"ima_fat.reach", RealRef([](Params& p) { return &p.ima_fat_reach; }), 1, 10,
     "d_max as a multiple of the vessel-to-wall gap"},
    {"fascia_fat.reach", RealRef([](Params& p) { return &p.fascia_fat_reach; }), 1, 10,
     "d_max as a multiple of the fat thickness"},

    {"coupling.lambda_max_m", RealRef([](Params& p) { return &p.patch.coupling_lambda_max; }), 0, 1,
     "lambda_max of eq. 8-9"},
    {"coupling.radius_m", RealRef([](Params& p) { return &p.patch.coupling_radius; }), 1e-5, 0.1,
     "strand particles this close to a surface are coupled to it"},

    {"ports.target_m", Vec3Ref([](Params& p) { return &p.port_target; }), -kRoom, kRoom,
     "where every port aims"},
    {"ports.camera_m", Vec3Ref([](Params& p) { return &p.ports[0].position; }), -kRoom, kRoom,
     "camera port on the left chest wall (Fig. 2e)"},
    {"ports.left_instrument_m", Vec3Ref([](Params& p) { return &p.ports[1].position; }), -kRoom,
     kRoom, "left instrument port"},
    {"ports.right_instrument_m", Vec3Ref([](Params& p) { return &p.ports[2].position; }), -kRoom,
     kRoom, "right instrument port"},
    {"ports.assistant_m", Vec3Ref([](Params& p) { return &p.ports[3].position; }), -kRoom, kRoom,
     "assistant port"},
    IMASIM_FORCE_KEYS("force_fascia", 0),
    IMASIM_FORCE_KEYS("force_fat", 1),
    IMASIM_FORCE_KEYS("force_ima", 2),
    IMASIM_FORCE_KEYS("force_heart", 3),
    IMASIM_FORCE_KEYS("force_chest_wall", 4),

    {"haptics.proxy_stiffness_n_per_m",
     RealRef([](Params& p) { return &p.console.proxy_stiffness; }), 1, 1e5,
     "the tool proxy's coupling to the device, every tissue's (stiff: the hand feels the tissue)"},
    {"haptics.proxy_damping_n_s_per_m", RealRef([](Params& p) { return &p.console.proxy_damping; }),
     0.01, 1e3, "the tool proxy's damper (> 0: 0 would make the tool rigid)"},
    {"haptics.device_max_force_n", RealRef([](Params& p) { return &p.console.device_max_force; }),
     0, 40, "the force a hand's device renders at most (desktop devices: 3.3 N)"},
    {"haptics.max_force_rate_n_per_s", RealRef([](Params& p) { return &p.console.max_force_rate; }),
     1, 1e5, "the fastest change of a commanded force"},
    {"haptics.ramp_s", RealRef([](Params& p) { return &p.console.ramp_s; }), 0, 10,
     "force ramp-in after start and after each clutch release"},
    {"haptics.stale_after_s", RealRef([](Params& p) { return &p.console.stale_after_s; }), 0.005, 1,
     "a local model older than this fades the force out (watchdog)"},
    {"haptics.fade_s", RealRef([](Params& p) { return &p.console.fade_s; }), 0, 1,
     "the watchdog's fade to zero"},
    {"haptics.motion_scale", RealRef([](Params& p) { return &p.console.motion_scale; }), 0.05, 2,
     "instrument motion per hand motion (robotic consoles: 1/3)"},
    {"haptics.tremor_cutoff_hz", RealRef([](Params& p) { return &p.console.tremor_cutoff_hz; }), 0,
     100, "low-pass on the hands' positions (0: off; tremor is 8-12 Hz)"},

    IMASIM_NAME_KEY("igtl_address", igtl_address,
                    "OpenIGTLink: where to listen, or the tracker's server to call (IPv4)"),
    {"devices.igtl_port", CountRef([](Params& p) { return &p.console.igtl_port; }), 0, 65535,
     "OpenIGTLink port (the protocol's is 18944; 0: any free)"},
    {"devices.igtl_allow_remote", BoolRef([](Params& p) { return &p.console.igtl_allow_remote; }),
     0, 0, "accept an address off this machine (false: loopback only)"},
    {"devices.igtl_idle_timeout_s",
     RealRef([](Params& p) { return &p.console.igtl_idle_timeout_s; }), 0, 3600,
     "OpenIGTLink: drop a peer that sends nothing whole this long (s; 0: never; it releases what "
     "the peer drove)"},
    {"devices.tracker_translation_m",
     Vec3Ref([](Params& p) { return &p.console.tracker_translation; }), -2, 2,
     "OpenIGTLink: the tracker's origin in the scene (every pose is moved by it)"},
    {"devices.tracker_rotation_deg",
     Vec3Ref([](Params& p) { return &p.console.tracker_rotation_deg; }), -360, 360,
     "OpenIGTLink: the tracker's frame turned into the scene's (about x, then y, then z)"},
    {"devices.tool_registration", ChoiceRef([](Params& p) { return &p.console.tool_registration; }),
     0, 0,
     "tool poses: fixed (where the tracker says) or clutch (moved from where the tool is at each "
     "clutch release)",
     kToolRegistrations},
    IMASIM_NAME_KEY("left_hand", left_hand, "TRANSFORM name of the left hand's pose (mm)"),
    IMASIM_NAME_KEY("right_hand", right_hand, "TRANSFORM name of the right hand's pose (mm)"),
    IMASIM_NAME_KEY("left_tool", left_tool, "TRANSFORM name of a tracked left instrument (mm)"),
    IMASIM_NAME_KEY("right_tool", right_tool, "TRANSFORM name of a tracked right instrument (mm)"),
    IMASIM_NAME_KEY("left_buttons", left_buttons, "SENSOR name of [clutch, jaw] of the left hand"),
    IMASIM_NAME_KEY("right_buttons", right_buttons,
                    "SENSOR name of [clutch, jaw] of the right hand"),
    IMASIM_NAME_KEY("pedal", pedal, "SENSOR name of [mode, power W] of the foot pedal"),
    IMASIM_NAME_KEY("left_force", left_force, "SENSOR name of the left hand's force out (N)"),
    IMASIM_NAME_KEY("right_force", right_force, "SENSOR name of the right hand's force out (N)"),

    {"devices.gamepad_speed_m_per_s", RealRef([](Params& p) { return &p.console.gamepad_speed; }),
     0.001, 1, "gamepad: hand speed at full stick deflection"},
    {"devices.gamepad_dead_zone", RealRef([](Params& p) { return &p.console.gamepad_dead_zone; }),
     0, 0.9, "gamepad: share of a stick's travel read as rest"},
    {"devices.gamepad_reach_m", RealRef([](Params& p) { return &p.console.gamepad_reach; }), 0.01,
     1, "gamepad: a hand's range from its start, per axis"},
    IMASIM_BUTTON_KEY("gamepad_cut_button", gamepad_cut_button, "gamepad: pedal cut while held"),
    IMASIM_BUTTON_KEY("gamepad_coag_button", gamepad_coag_button,
                      "gamepad: pedal coagulation while held"),
    IMASIM_BUTTON_KEY("gamepad_left_clutch_button", gamepad_left_clutch_button,
                      "gamepad: left clutch while held"),
    IMASIM_BUTTON_KEY("gamepad_right_clutch_button", gamepad_right_clutch_button,
                      "gamepad: right clutch while held"),
    {"devices.spacemouse_hand", ChoiceRef([](Params& p) { return &p.console.spacemouse_hand; }), 0,
     0, "3D mouse: the hand it moves", kHandNames},
    {"devices.spacemouse_speed_m_per_s",
     RealRef([](Params& p) { return &p.console.spacemouse_speed; }), 0.001, 1,
     "3D mouse: hand speed at full push"},
    {"devices.spacemouse_turn_rate_rad_per_s",
     RealRef([](Params& p) { return &p.console.spacemouse_turn_rate; }), 0, 10,
     "3D mouse: hand turn rate at full twist"},
    {"devices.spacemouse_dead_zone",
     RealRef([](Params& p) { return &p.console.spacemouse_dead_zone; }), 0, 0.9,
     "3D mouse: share of full push read as rest"},
    {"devices.spacemouse_jaw_button",
     CountRef([](Params& p) { return &p.console.spacemouse_jaw_button; }), 0, 1,
     "3D mouse: the button that closes the jaw while held (0 or 1)"},
    {"devices.spacemouse_clutch_button",
     CountRef([](Params& p) { return &p.console.spacemouse_clutch_button; }), 0, 1,
     "3D mouse: the button that clutches while held (0 or 1)"},
    IMASIM_NAME_KEY("pedal_joystick", pedal_joystick,
                    "foot pedals: the joystick whose name contains this (\"any\": the first "
                    "that is not a gamepad)"),
    {"devices.pedal_cut_button", CountRef([](Params& p) { return &p.console.pedal_cut_button; }), 0,
     kUnmappedPedalButton, "foot pedals: the button for cut (32: none)"},
    {"devices.pedal_coag_button", CountRef([](Params& p) { return &p.console.pedal_coag_button; }),
     0, kUnmappedPedalButton, "foot pedals: the button for coagulation (32: none)"},
    {"devices.pedal_clutch_button",
     CountRef([](Params& p) { return &p.console.pedal_clutch_button; }), 0, kUnmappedPedalButton,
     "foot pedals: the button clutching both hands (32: none)"},
};

#undef IMASIM_STRAND_KEYS
#undef IMASIM_BUTTON_KEY

constexpr std::array<std::string_view, 17> kTables = {
    "anatomy",      "solver",    "heart",      "chest_wall",  "fascia",
    "vessel",       "ima_fat",   "fascia_fat", "coupling",    "ports",
    "force_fascia", "force_fat", "force_ima",  "force_heart", "force_chest_wall",
    "haptics",      "devices"};

}  // namespace

std::span<const SceneKey> scene_keys() {
  return kKeys;
}
std::span<const std::string_view> scene_tables() {
  return kTables;
}

}  // namespace imasim::scene
