#pragma once
// The press probe behind `imasim press`: the cautery hook pressed into one tissue of
// a scene, tip first along the tissue's inward normal, held and settled at each depth past the
// tissue's resting surface, and the force the hand then receives (eq. 17-18 through the local
// model, as the 1 kHz loop renders it, the device still) beside the table's k_d d (eq. 17 with the
// depth past the resting surface). Soft tissue that gives way lets the tool's proxy follow the
// device, so what the hand gets falls short of k_d d; a rigid surface stops the proxy and gives
// k_d d (docs/haptics.md, "The press probe").
//
// Sites: along the IMA where the heart is farthest (press_probe.cpp), the fascia's vertex nearest;
// the IMA's vertex facing the cavity and the fat's lowest particle beside the vessel, both with
// the fascia taken away as after it is opened (its particles fixed and moved off the field, its
// strands divided); the heart's surface nearest the hook's port; the chest wall 10 mm lateral of
// the fascia's edge. The heart is held at its static phase so that the press settles.
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "haptics/force_params.hpp"
#include "physics/executor.hpp"
#include "scene/thorax_scene.hpp"

namespace imasim::console {

enum class PressTissue : std::uint8_t { fascia, fat, ima, heart, wall };
inline constexpr std::size_t kPressTissues = 5;

const char* press_tissue_name(PressTissue tissue);
// "fascia", "fat", "ima", "heart" or "wall"; empty for anything else.
std::optional<PressTissue> press_tissue_named(std::string_view name);

struct PressSettings {
  Real approach_speed = Real(0.02);  // free travel to the start of the press (unit: m/s)
  Real press_speed = Real(0.005);    // into the tissue, from depth to depth (unit: m/s)
  Real clearance = Real(0.003);      // the press starts this far out of the surface (unit: m)
  double settle_s = 0.4;             // held at each depth before the force is read (unit: s)
  double average_s = 0.1;            // the force is the mean over the hold's last part (unit: s)
};

struct PressPoint {
  double depth_m = 0;  // of the device's tip past the resting surface (unit: m)
  double force_n = 0;  // eq. 17's normal channel the device receives (unit: N)
  // Everything the device receives along the press direction: eq. 17 and eq. 18's friction.
  double force_along_press_n = 0;  // (unit: N)
  double law_n = 0;                // k_d depth (unit: N)
  double proxy_depth_m = 0;        // how far the tool itself went past the resting surface (m)
};

struct PressResult {
  PressTissue tissue = PressTissue::fascia;
  Vec3 site = Vec3::Zero();        // on the resting surface (unit: m)
  Vec3 normal = Vec3::UnitY();     // out of the tissue there
  Real k_d = 0;                    // the table's (unit: N/m)
  std::vector<PressPoint> points;  // by ascending depth
  std::uint64_t steps = 0;
};

// Throws std::invalid_argument for depths outside (0, 15 mm] (the proxy's bound) and what
// make_surgical_session throws. `params` is taken as given except that the heart is held.
PressResult press_tissue(const scene::ThoraxSceneParams& params, PressTissue tissue,
                         std::span<const double> depths_m, const PressSettings& settings,
                         physics::Executor& exec);

}  // namespace imasim::console
