#pragma once
// The thorax scene: the procedural thorax of a virtual patient (scene/anatomy.hpp) laid out as
// the thoracic-wall patch (tissue/thoracic_patch.hpp), the beating heart under the left IMA
// (procedural, or a phase series from files), the display-only chest skeleton and the ports.
// One step, in the order of the architecture: advance the heart (or hold it, static mode) and
// move the anchored boundary with it; engine step, XSPH, couplings; the heart as a collider;
// surfaces, the fine vessel and the strand ends.
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "physics/executor.hpp"
#include "physics/step.hpp"
#include "scene/anatomy.hpp"
#include "scene/chest_skeleton.hpp"
#include "scene/console_settings.hpp"
#include "scene/heart_series.hpp"
#include "scene/implicit_mesh_scene.hpp"
#include "scene/ports.hpp"
#include "tissue/heart_field.hpp"
#include "tissue/surface_contacts.hpp"
#include "tissue/thoracic_patch.hpp"

namespace imasim::scene {

// The solvers a mesh of the scene can have (fascia.solver, vessel.solver).
inline constexpr std::string_view kXpbdFasciaSolver = "xpbd";
inline constexpr std::string_view kImplicitFasciaSolver = "implicit";

struct ThoraxSceneParams {
  AnatomyParams anatomy;
  // Materials, resolutions and generation settings. Its geometry (the wall's placement and
  // span, the vessel's centerline, the fascia's extent and pose, the strands' d_max) is laid
  // out from the anatomy when the scene is made.
  tissue::ThoracicPatchParams patch;
  // d_max of each strand set as a multiple of the gap its strands bridge: vessel surface to
  // wall for the IMA's fat, fascia to wall for the fascia's (2.3.4).
  Real ima_fat_reach = Real(2.2), fascia_fat_reach = Real(1.5);
  // The procedural heart's shape and orientation; the anatomy places and scales it.
  tissue::HeartParams heart;
  HeartSeriesSpec heart_series;  // phase files replace the procedural heart when given
  tissue::HeartPlayback playback;
  std::vector<Port> ports;          // camera, left and right instrument, assistant
  Vec3 port_target = Vec3::Zero();  // where the ports aim (unit: m)
  ConsoleSettings console = default_console_settings();  // forces, safety, devices
  // The fascia's solver (docs/physics.md): "xpbd", its rows in the step's sweeps, at the toe's
  // modulus (fascia.youngs_modulus_pa) at every strain; "implicit", Newton on the backward-Euler
  // step (implicit_mesh_scene.hpp) with the strain-stiffening law: the toe's modulus at rest,
  // the linear region's past the toe strain.
  std::string fascia_solver = std::string(kXpbdFasciaSolver);
  Real fascia_linear_modulus = Real(2.65e6);  // E past the toe strain (unit: Pa; implicit only)
  Real fascia_toe_strain = Real(0.05);        // where the toe ends (implicit only)
  // The vessel's solver: "implicit" (the default), Newton on the backward-Euler step of its
  // rows' energy (implicit_mesh_scene.hpp), which the stiff rows along the vessel need to push
  // back on a tool as they would converged; "xpbd", its rows in the step's sweeps (the coarse band
  // unless patch.vessel.object.coarse is false), a fifth as stiff under a hook (docs/physics.md).
  std::string vessel_solver = std::string(kImplicitFasciaSolver);
  // What reading the scene file said that is not an error, "FILE:LINE: ..." (an old key read
  // under its new name); make_thorax_scene passes them on as setup notes.
  std::vector<std::string> file_notes;
};

ThoraxSceneParams default_thorax_scene_params();

// The patch parameters for a patient: `params.patch` with the anatomy's geometry.
tissue::ThoracicPatchParams lay_out_patch(const ThoraxSceneParams& params,
                                          const AnatomyParams& patient, const ThoraxLayout& layout);

struct ThoraxScene {
  AnatomyParams patient;  // the anatomy after seeded variation
  ThoraxLayout layout;
  tissue::ThoracicPatch patch;
  tissue::HeartField heart;
  tissue::SurfaceContactParams contact;
  // Particles the solve's contacts missed and the step's check found inside the heart (put out
  // after the step, a warning: the search should have caught them).
  std::uint32_t missed_heart_contacts = 0;
  tissue::WallAndFloorChunks wall_and_floor_chunks;  // their gathering's rows per chunk
  std::vector<DisplayMesh> skeleton;                 // display only
  std::vector<Port> ports;
  // What set-up repaired or decided on the user's behalf (a capped heart mesh, an automatic
  // placement), for the user to read.
  std::vector<std::string> setup_notes;
  // The fascia solved by the implicit membrane step instead of its XPBD rows
  // (fascia_solver "implicit", or use_implicit_fascia), or XPBD when empty.
  std::optional<SceneImplicitMesh> implicit_fascia;
  // The vessel solved by the implicit step of its own rows' energy (vessel_solver "implicit", or
  // use_implicit_vessel), or XPBD when empty.
  std::optional<SceneImplicitMesh> implicit_vessel;
};

// Throws MeshFileError when a heart phase file cannot be loaded, HeartPlacementError when the
// heart starts inside the tissue or through the chest wall.
ThoraxScene make_thorax_scene(const ThoraxSceneParams& params);

physics::StepResult step_thorax_scene(ThoraxScene& scene, physics::Executor& exec);

// The two halves of step_thorax_scene, for a caller that adds its own contacts in between (the
// surgical session's instruments): advance the heart and gather the heart's and the wall's
// contacts for the coming step; then the step itself (tissue dynamics with the contacts inside
// the solve, the check for missed heart contacts, surfaces). The first adds the time of its
// stages to `profile`; the second's result carries the step's. Both search the heart on exec's
// threads.
void prepare_thorax_step(ThoraxScene& scene, physics::StepProfile& profile,
                         const physics::Executor& exec);
physics::StepResult finish_thorax_step(ThoraxScene& scene, physics::Executor& exec);

// Heart contacts in touch at the end of the last step.
std::uint32_t heart_contacts(const ThoraxScene& scene);

}  // namespace imasim::scene
