#pragma once
// The procedural thorax (SPEC S3): a few anatomical parameters of a virtual patient, their
// physiological ranges, seeded variation between patients, and the layout they give the
// simulated tissues (chest wall, IMA course, fascia, strand lengths, heart placement).
//
// Frame: x lateral (towards the patient's left), y from the thoracic cavity towards the chest
// wall (the surgeon, inside the cavity, looks along +y at the wall), z along the IMA's course
// (cranial end at the sternum position's z, caudal +z). The chest wall's inner surface is a
// cylinder about an axis parallel to z, its apex on the sternum's midline.
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "geometry/tube.hpp"
#include "math/pose.hpp"

namespace imasim::scene {

struct AnatomyParams {
  Vec3 sternum_position = Vec3(Real(-0.025), 0, 0);  // inner-surface midline, cranial end (m)
  Real sternum_width = Real(0.03);                   // (unit: m)
  Real ima_lateral_offset = Real(0.025);  // IMA centre from the sternum's midline (unit: m)
  Real ima_lateral_drift = Real(0.005);   // extra lateral offset at the caudal end (unit: m)
  Real ima_depth = Real(0.004);           // IMA centre under the wall's inner surface (m)
  Real ima_course_length = Real(0.15);    // >= 0.15 m, so a 10 cm segment can be harvested
  Real chest_wall_radius = Real(0.12);    // transverse curvature radius of the wall (unit: m)
  Real fat_thickness = Real(0.01);        // wall to fascia (unit: m)
  Real fascia_width = Real(0.04);         // fascia extent across the IMA (unit: m)
  Real fascia_length = Real(0.15);        // fascia extent along the IMA (unit: m)
  Real rib_spacing = Real(0.025);         // cranio-caudal pitch of the ribs (unit: m)
  Real heart_scale = 1;                   // on the heart's lengths and radii
  // LV centre from the IMA's mid-course centre (unit: m): under the left IMA, in the cavity.
  Vec3 heart_offset = Vec3(Real(0.005), Real(-0.034), Real(0.015));
  Vec3 heart_tilt = Vec3::Zero();  // axis * angle applied to the heart's orientation (rad)
  // The cavity's floor under the field: the collapsed left lung and the pericardium beside the
  // heart, as a horizontal plane this far below the lowest tissue at rest (about the default
  // heart's centre: ours); tissue cut free rests on it instead of falling across the cavity.
  Real cavity_floor_gap = Real(0.02);  // (unit: m)
  std::uint64_t patient_seed = 0;      // 0: this typical patient; else a varied one (see below)
};

// A varied scalar parameter: its physiological range. Variation draws each one from a
// triangular distribution on [min, max] with its mode at the typical value (clamped into the
// range); vector parameters vary per component by +- `spread`.
struct AnatomyRange {
  std::string_view name;
  Real AnatomyParams::*member;
  Real min, max;
};
std::span<const AnatomyRange> anatomy_ranges();

struct AnatomyVectorSpread {
  std::string_view name;
  Vec3 AnatomyParams::*member;
  Vec3 spread;  // +- per component, triangular about the typical value (unit: m or rad)
};
std::span<const AnatomyVectorSpread> anatomy_vector_spreads();

// The patient for `typical.patient_seed`: `typical` itself for seed 0, else every varied
// parameter drawn as above from a SplitMix64 stream of the seed (same seed, same patient).
AnatomyParams vary_anatomy(const AnatomyParams& typical);

// What the anatomy fixes in the simulated scene.
struct ThoraxLayout {
  geometry::CylinderPatchSpec wall;  // all but the resolution (nu, nv)
  std::vector<Vec3> ima_centerline;  // cranial to caudal
  Pose fascia_pose;                  // of the fascia rectangle (local x-z plane, normal +y)
  Vec3 heart_centre, heart_long_axis, heart_lateral;
  Vec3 ima_midpoint;
  Real wall_axis_y = 0;  // the cylinder axis: (sternum x, wall_axis_y, z)
  // The floor plane y = cavity_floor_y, its normal +y (set with the tissue: make_thorax_scene).
  Real cavity_floor_y = 0;
};

// `long_axis` and `lateral` are the heart's orientation before the tilt.
ThoraxLayout layout_thorax(const AnatomyParams& anatomy, const Vec3& heart_long_axis,
                           const Vec3& heart_lateral);

// Point of the wall's inner surface at lateral position x (unit: m) and height z, and the unit
// normal there pointing out of the cavity (into the wall).
Vec3 wall_point(const AnatomyParams& anatomy, Real x, Real z);
Vec3 wall_outward_normal(const AnatomyParams& anatomy, Real x);

}  // namespace imasim::scene
