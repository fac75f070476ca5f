#include "scene/mesh_file.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cstring>
#include <filesystem>
#include <map>
#include <tuple>

#include "scene/mesh_file_limits.hpp"

namespace imasim::scene {

Vec3 MeshTransform::apply(const Vec3& file_point) const {
  const Real angle = rotation.norm();
  const Vec3 scaled = scale * file_point;
  const Vec3 turned = angle > 0 ? Vec3(axis_angle(rotation / angle, angle) * scaled) : scaled;
  return turned + translation;
}

namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw MeshFileError(path + ": " + what);
}

// The triangles of every mesh of the scene, welded: vertices with the same position (bit for
// bit, as the file gives them) become one, numbered in order of first use.
geometry::TriangleMesh weld(const aiScene& scene, const MeshTransform& transform) {
  geometry::TriangleMesh mesh;
  std::map<std::tuple<float, float, float>, std::uint32_t> index;
  for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
    const aiMesh& in = *scene.mMeshes[m];
    for (unsigned f = 0; f < in.mNumFaces; ++f) {
      const aiFace& face = in.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines carry no surface
      geometry::Triangle tri;
      for (int k = 0; k < 3; ++k) {
        const aiVector3D& v = in.mVertices[face.mIndices[k]];
        const auto [it, added] =
            index.try_emplace({v.x, v.y, v.z}, static_cast<std::uint32_t>(mesh.vertices.size()));
        if (added) mesh.vertices.push_back(transform.apply(Vec3(Real(v.x), Real(v.y), Real(v.z))));
        tri[k] = it->second;
      }
      mesh.triangles.push_back(tri);
    }
  }
  return mesh;
}

}  // namespace

geometry::TriangleMesh load_mesh_file(const std::string& path, const MeshLoadOptions& options) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail(path, "no such file");
  if (!std::filesystem::is_regular_file(path, ec)) fail(path, "not a regular file");
  if (!(options.transform.scale > 0) || !options.transform.rotation.allFinite() ||
      !options.transform.translation.allFinite()) {
    fail(path, "the mesh transform needs a positive scale and finite rotation and translation");
  }
  if (std::string problem = mesh_file_problem(path); !problem.empty()) fail(path, problem);
  Assimp::Importer importer;
  // Only surface data matters: drop lines and points, bake the node hierarchy into the vertices.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_SortByPType |
                                  aiProcess_PreTransformVertices | aiProcess_ValidateDataStructure);
  if (scene == nullptr) {
    const char* why = importer.GetErrorString();
    fail(path, std::string("cannot read the mesh: ") +
                   (why != nullptr && std::strlen(why) > 0 ? why : "unknown format"));
  }
  // Before welding: a NaN would break the ordering of the weld's map.
  if (std::string problem = mesh_coordinate_problem(*scene); !problem.empty()) fail(path, problem);
  geometry::TriangleMesh mesh = weld(*scene, options.transform);
  if (mesh.triangles.empty()) fail(path, "the file holds no triangles");
  if (!options.run_checks) return mesh;
  if (std::string defect = geometry::first_mesh_defect(mesh, options.checks); !defect.empty())
    fail(path, defect);
  return mesh;
}

}  // namespace imasim::scene
