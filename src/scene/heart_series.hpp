#pragma once
// A 4D heart from files (SPEC S3): one closed surface mesh per cardiac phase, all with one
// topology, phase k at cycle fraction k / N. Each file goes through load_mesh_file with the
// same transform; the surfaces must be closed, outward-facing manifolds. Connected components
// (e.g. the two ventricles) become the heart model's components.
#include <string>
#include <vector>

#include "scene/mesh_file.hpp"
#include "tissue/heart.hpp"

namespace imasim::scene {

struct HeartSeriesSpec {
  std::vector<std::string> phase_files;  // in cycle order; empty = the procedural heart
  MeshTransform transform;
};

// Throws MeshFileError naming the file at fault (a mesh defect, a phase whose topology differs
// from the first, a surface facing inwards, fewer than two phases).
tissue::HeartModel load_heart_series(const HeartSeriesSpec& spec);

}  // namespace imasim::scene
