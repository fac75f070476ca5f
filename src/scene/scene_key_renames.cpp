#include "scene/scene_key_renames.hpp"

#include <array>

namespace imasim::scene {

namespace {

constexpr std::string_view kDampingWhy =
    "k_l of eq. 4, the paper's 0.03: the share of velocity removed per 5 ms, as the paper's "
    "engine reads it (the unit kg/s was a misreading)";

constexpr std::array<RenamedSceneKey, 8> kRenamed = {{
    {"fascia.linear_damping_kg_per_s", "fascia.linear_damping", KeyConversion::same, kDampingWhy},
    {"ima_fat.linear_damping_kg_per_s", "ima_fat.linear_damping", KeyConversion::same, kDampingWhy},
    {"fascia_fat.linear_damping_kg_per_s", "fascia_fat.linear_damping", KeyConversion::same,
     kDampingWhy},
    {"fascia.angular_damping_kg_m2_per_s", "fascia.angular_damping", KeyConversion::same,
     "k_c of eq. 4, the paper's 0.01: the share of the non-rigid velocity removed per 5 ms (the "
     "unit kg m^2/s was a misreading)"},
    {"fascia.width_m", "anatomy.fascia_width_m", KeyConversion::same,
     "the fascia's extent across the IMA, laid out from the anatomy"},
    {"fascia.height_m", "anatomy.fascia_length_m", KeyConversion::same,
     "the fascia's extent along the IMA, laid out from the anatomy"},
    {"ima_fat.max_length_m", "ima_fat.reach", KeyConversion::per_ima_fat_gap,
     "d_max as a multiple of the vessel-to-wall gap (anatomy.ima_depth_m - vessel.radius_m), so "
     "that it follows a patient's anatomy"},
    {"fascia_fat.max_length_m", "fascia_fat.reach", KeyConversion::per_fat_thickness,
     "d_max as a multiple of the fat's thickness (anatomy.fat_thickness_m), so that it follows a "
     "patient's anatomy"},
}};

constexpr std::string_view kWallLayout =
    "the chest wall is laid out from the anatomy: anatomy.chest_wall_radius_m, "
    "anatomy.sternum_position_m, anatomy.ima_course_length_m (its resolution stays "
    "chest_wall.nu, chest_wall.nv)";
constexpr std::string_view kFasciaStretch =
    "fascia.youngs_modulus_pa and fascia.thickness_m: each stretch row's compliance follows from "
    "E t and its edge's rest geometry, alpha = |e|^2 / (E t sum A), so it no longer depends on the "
    "mesh";
constexpr std::string_view kVesselStretch =
    "vessel.youngs_modulus_pa and vessel.wall_thickness_m (stretch E t per edge's rest geometry)";
constexpr std::string_view kStrandStiffness =
    "the set's youngs_modulus_pa: a segment of length L over its share A_s of its face has "
    "k = E A_s / L";

constexpr std::array<RetiredSceneKey, 16> kRetired = {{
    {"chest_wall.radius_m", kWallLayout},
    {"chest_wall.origin_m", kWallLayout},
    {"chest_wall.axis", kWallLayout},
    {"chest_wall.angle0_rad", kWallLayout},
    {"chest_wall.angle1_rad", kWallLayout},
    {"chest_wall.length_m", kWallLayout},
    {"chest_wall.reference", kWallLayout},
    {"fascia.origin_m",
     "the fascia is laid out from the anatomy: anatomy.fat_thickness_m below the wall, over the "
     "IMA"},
    {"vessel.centerline_m",
     "the IMA's course is laid out from the anatomy: anatomy.ima_lateral_offset_m, "
     "anatomy.ima_lateral_drift_m, anatomy.ima_depth_m, anatomy.ima_course_length_m"},
    {"heart.centre_m", "anatomy.heart_offset_m, the LV centre from the IMA's mid-course centre"},
    {"fascia.stretch_compliance_m_per_n", kFasciaStretch},
    {"fascia.bending_compliance_rad_per_n_m",
     "fascia.bending_stiffness_n_m (D; 0 = the plate's E t^3 / (12 (1 - nu^2)))"},
    {"vessel.stretch_compliance_m_per_n", kVesselStretch},
    {"vessel.bending_compliance_rad_per_n_m",
     "the wall's plate bending E t^3 / (12 (1 - nu^2)) from vessel.youngs_modulus_pa and "
     "vessel.wall_thickness_m"},
    {"ima_fat.compliance_m_per_n", kStrandStiffness},
    {"fascia_fat.compliance_m_per_n", kStrandStiffness},
}};

}  // namespace

std::span<const RenamedSceneKey> renamed_scene_keys() {
  return kRenamed;
}
std::span<const RetiredSceneKey> retired_scene_keys() {
  return kRetired;
}

const RenamedSceneKey* find_renamed_scene_key(std::string_view path) {
  for (const RenamedSceneKey& k : kRenamed)
    if (k.old_path == path) return &k;
  return nullptr;
}

const RetiredSceneKey* find_retired_scene_key(std::string_view path) {
  for (const RetiredSceneKey& k : kRetired)
    if (k.old_path == path) return &k;
  return nullptr;
}

}  // namespace imasim::scene
