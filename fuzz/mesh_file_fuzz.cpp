// libFuzzer target: mesh files of one format (IMASIM_FUZZ_MESH_EXTENSION: ".obj", ".stl",
// ".ply" or ".gltf"), read as the scene reads a heart phase or a chest-wall surface: from a file,
// through the size checks, Assimp, the coordinate checks, the weld and the manifold checks, and
// as a heart phase series (repairs, size, orientation, components). Any bytes are either refused
// with MeshFileError or give a mesh whose triangles index its vertices, never a crash or a hang.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "fuzz_check.hpp"
#include "scene/heart_series.hpp"
#include "scene/mesh_file.hpp"

#ifndef IMASIM_FUZZ_MESH_EXTENSION
#error "IMASIM_FUZZ_MESH_EXTENSION names the format, e.g. \".obj\""
#endif

namespace {

// One file per fuzzing process, rewritten for each input (the loader reads paths, as users give
// them; its size and header checks are part of what is fuzzed).
const std::string& scratch_path() {
  static const std::string path =
      "/tmp/imasim-fuzz-" + std::to_string(::getpid()) + IMASIM_FUZZ_MESH_EXTENSION;
  return path;
}

void write_scratch(const std::uint8_t* data, std::size_t size) {
  std::FILE* f = std::fopen(scratch_path().c_str(), "wb");
  imasim::fuzz::require(f != nullptr, "cannot write the scratch file " + scratch_path());
  const bool written = size == 0 || std::fwrite(data, 1, size, f) == size;
  imasim::fuzz::require(std::fclose(f) == 0 && written, "cannot write " + scratch_path());
}

void check_indices(const imasim::geometry::TriangleMesh& mesh) {
  for (const imasim::geometry::Triangle& t : mesh.triangles) {
    for (const auto v : t)
      imasim::fuzz::require(v < mesh.vertices.size(), "a triangle indexes past the vertices");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace imasim;
  write_scratch(data, size);
  // As a chest-wall surface: checked.
  try {
    check_indices(scene::load_mesh_file(scratch_path()));
  } catch (const scene::MeshFileError&) {
  }
  // As a heart phase series (the same file twice): repaired, checked, split into components.
  scene::HeartSeriesSpec heart;
  heart.phase_files = {scratch_path(), scratch_path()};
  std::vector<std::string> notes;
  try {
    const tissue::HeartModel model = scene::load_heart_series(heart, &notes);
    check_indices(model.topology);
    for (const std::vector<Vec3>& frame : model.keyframes)
      imasim::fuzz::require(frame.size() == model.topology.vertices.size(),
                            "a heart phase has another vertex count");
  } catch (const scene::MeshFileError&) {
  }
  return 0;
}
