#include "scene/mesh_import.hpp"

#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <assimp/Importer.hpp>
#include <cstring>

#include "scene/mesh_file_limits.hpp"

namespace imasim::scene {

std::vector<float> import_triangle_corners(const std::string& path) {
  Assimp::Importer importer;
  // Only surface data matters: drop lines and points, bake the node hierarchy into the vertices.
  importer.SetPropertyInteger(AI_CONFIG_PP_SBP_REMOVE,
                              aiPrimitiveType_POINT | aiPrimitiveType_LINE);
  const aiScene* scene = nullptr;
  try {
    scene = importer.ReadFile(path, aiProcess_ValidateDataStructure | aiProcess_Triangulate |
                                        aiProcess_SortByPType | aiProcess_PreTransformVertices);
  } catch (const std::exception& e) {
    throw MeshImportError(std::string("cannot read the mesh: ") + e.what());
  }
  if (scene == nullptr) {
    const char* why = importer.GetErrorString();
    throw MeshImportError(std::string("cannot read the mesh: ") +
                          (why != nullptr && std::strlen(why) > 0 ? why : "unknown format"));
  }
  if (std::string problem = mesh_coordinate_problem(*scene); !problem.empty())
    throw MeshImportError(problem);
  std::vector<float> corners;
  for (unsigned m = 0; m < scene->mNumMeshes; ++m) {
    const aiMesh& mesh = *scene->mMeshes[m];
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
      const aiFace& face = mesh.mFaces[f];
      if (face.mNumIndices != 3) continue;  // points and lines carry no surface
      for (int k = 0; k < 3; ++k) {
        if (face.mIndices[k] >= mesh.mNumVertices) {
          throw MeshImportError("face " + std::to_string(f) + " uses vertex " +
                                std::to_string(face.mIndices[k]) + " of a mesh of " +
                                std::to_string(mesh.mNumVertices));
        }
        const aiVector3D& v = mesh.mVertices[face.mIndices[k]];
        corners.insert(corners.end(), {v.x, v.y, v.z});
      }
    }
  }
  return corners;
}

}  // namespace imasim::scene
