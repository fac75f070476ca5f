#pragma once
// Where a heart loaded from phase files goes, and the check that it does not start inside the
// tissue or through the chest wall (a patient's segmentation is in scanner coordinates, not
// ours). heart.placement = "auto" places it from its own shape: its long axis (the principal
// axis of largest spread), which end is the apex (the narrower end: a ventricle tapers to its
// apex and is wide, or open and capped, at its base) and its centre, turned onto the scene's
// heart axes, centred where the anatomy puts the heart, and moved along the line from there to
// the IMA until its closest approach to the IMA's course over the whole cycle is the built-in
// heart's. Scale stays the patient's. "file" keeps the mesh_scale / rotation / translation
// transform alone.
#include <stdexcept>
#include <string>

#include "scene/anatomy.hpp"
#include "tissue/heart.hpp"
#include "tissue/heart_field.hpp"
#include "tissue/tissue_world.hpp"

namespace imasim::scene {

class HeartPlacementError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The shape of a heart mesh from its first keyframe (unit: m).
struct HeartShape {
  Vec3 centre = Vec3::Zero();        // mean of the vertices
  Vec3 long_axis = Vec3::UnitZ();    // unit, base -> apex
  Vec3 second_axis = Vec3::UnitX();  // unit, across; towards the smaller ventricle if two
  Real length = 0;                   // extent along the long axis
};
HeartShape measure_heart_shape(const tissue::HeartModel& heart);

// Moves every keyframe of `heart` rigidly as described above; `reference` is the built-in heart
// of the same layout, whose clearance from the IMA it matches. Returns a note saying where it went.
std::string place_heart_automatically(tissue::HeartModel& heart, const ThoraxLayout& layout,
                                      const tissue::HeartModel& reference);

// How deep the fascia, the IMA or the chest wall may start inside the heart before set-up refuses
// (unit: m). Shallower overlaps are put out once at set-up, as they always were: the built-in
// anatomy's layout starts the fascia 1.5 mm inside the typical patient's heart and up to 5 mm
// inside some seeded patients'. A heart from files gets 2 mm (the built-in heart written to
// files and loaded back must load; more is a placement error, scanner coordinates); the
// built-in heart 8 mm, which catches an offset or size that puts it into the tissue without
// refusing the seeded patients.
inline constexpr Real kLoadedHeartOverlapTolerance = Real(0.002);
inline constexpr Real kBuiltinHeartOverlapTolerance = Real(0.008);

// Throws HeartPlacementError when, at the heart's current shape, vertices of the fascia, the IMA
// or the chest wall lie deeper than `tolerance` inside it, or heart vertices lie outside the
// chest wall's inner surface by more than `tolerance`: the message says how far, how many, and
// what to change (`remedy`: the scene keys to change).
void check_heart_placement(tissue::HeartField& heart, const tissue::TissueWorld& world,
                           const ThoraxLayout& layout, Real tolerance, const std::string& remedy);

}  // namespace imasim::scene
