#pragma once
// A 4D heart from files (SPEC S3): one surface mesh per cardiac phase, all with one topology,
// phase k at cycle fraction k / N. Each file goes through load_mesh_file with the same
// transform; after the repairs below the surfaces must be closed, outward-facing manifolds.
// Connected components (e.g. the two ventricles) become the heart model's components.
#include <string>
#include <vector>

#include "scene/mesh_file.hpp"
#include "tissue/heart.hpp"

namespace imasim::scene {

// heart.placement: "file" (the transform alone) or "auto" (scene/heart_placement.hpp).
inline constexpr const char* kFilePlacement = "file";
inline constexpr const char* kAutoPlacement = "auto";

struct HeartSeriesSpec {
  std::vector<std::string> phase_files;  // in cycle order; empty = the procedural heart
  MeshTransform transform;
  std::string placement = kFilePlacement;
};

// Welded coincident vertices (a segmentation's repeated apex pole) leave triangles with a repeated
// vertex: they are dropped. An open surface (a ventricle open at its valve plane) has each
// boundary loop capped (geometry/mesh_repair.hpp). Each repair adds a line to `notes`. Throws
// MeshFileError naming the file at fault (a mesh defect left after the repairs, a phase whose
// topology differs from the first, a surface facing inwards, fewer than two phases).
tissue::HeartModel load_heart_series(const HeartSeriesSpec& spec,
                                     std::vector<std::string>* notes = nullptr);

}  // namespace imasim::scene
