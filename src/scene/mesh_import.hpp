#pragma once
// The triangles of a mesh file as Assimp reads them: every triangle of every mesh, with the
// file's node transforms applied, as nine floats each (three corners, x y z, in file units).
// Faces that index past their mesh's vertices, and non-finite or absurd coordinates, are
// refused here, before anything trusts them.
#include <stdexcept>
#include <string>
#include <vector>

namespace imasim::scene {

class MeshImportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Reads in this process. Throws MeshImportError with Assimp's reason or the defect found.
std::vector<float> import_triangle_corners(const std::string& path);

// Reads in a child process, so that a malformed file that crashes or hangs Debian's Assimp
// (fuzzing found an abort on a failed internal check, a bus error in triangulation and a read
// loop that never ends, all on PLY files) ends that child, not imasim: the child's death or a
// time limit (10 s plus 1 s per 4 MiB of file) becomes a MeshImportError.
std::vector<float> import_triangle_corners_isolated(const std::string& path);

}  // namespace imasim::scene
