#pragma once
// Surface meshes from files (OBJ, STL, PLY, glTF 2.0) through Assimp: every triangle of every
// mesh in the file, with node transforms applied, welded by exact position into one indexed
// mesh, scaled (files are in millimetres by default) and placed by a per-mesh transform, then
// checked (geometry/mesh_checks.hpp). Every failure is a MeshFileError whose message starts with
// the file's path: missing, unreadable or corrupt, empty, degenerate or not a manifold.
#include <stdexcept>
#include <string>

#include "geometry/mesh_checks.hpp"
#include "geometry/triangle_mesh.hpp"
#include "math/pose.hpp"

namespace imasim::scene {

// x_scene = R (scale x_file) + translation, R the rotation by |rotation| rad about rotation.
struct MeshTransform {
  Real scale = Real(0.001);         // file units -> m (default: the file is in mm)
  Vec3 rotation = Vec3::Zero();     // axis * angle (unit: rad)
  Vec3 translation = Vec3::Zero();  // (unit: m)

  Vec3 apply(const Vec3& file_point) const;
};

struct MeshLoadOptions {
  MeshTransform transform;
  geometry::MeshCheckOptions checks;
  bool run_checks = true;  // false: the caller repairs the welded mesh and checks it itself
};

class MeshFileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws MeshFileError naming the file: "path: what".
[[noreturn]] inline void fail_mesh_file(const std::string& path, const std::string& what) {
  throw MeshFileError(path + ": " + what);
}

geometry::TriangleMesh load_mesh_file(const std::string& path, const MeshLoadOptions& options = {});

}  // namespace imasim::scene
