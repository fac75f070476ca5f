#include "scene/mesh_file.hpp"

#include <filesystem>
#include <map>
#include <tuple>

#include "scene/mesh_file_limits.hpp"
#include "scene/mesh_import.hpp"

namespace imasim::scene {

Vec3 MeshTransform::apply(const Vec3& file_point) const {
  const Real angle = rotation.norm();
  const Vec3 scaled = scale * file_point;
  const Vec3 turned = angle > 0 ? Vec3(axis_angle(rotation / angle, angle) * scaled) : scaled;
  return turned + translation;
}

namespace {

// The triangles (nine floats each), welded: vertices with the same position (bit for bit, as
// the file gives them) become one, numbered in order of first use.
geometry::TriangleMesh weld(const std::vector<float>& corners, const MeshTransform& transform) {
  geometry::TriangleMesh mesh;
  std::map<std::tuple<float, float, float>, std::uint32_t> index;
  for (std::size_t c = 0; c + 9 <= corners.size(); c += 9) {
    geometry::Triangle tri;
    for (std::size_t k = 0; k < 3; ++k) {
      const float x = corners[c + 3 * k], y = corners[c + 3 * k + 1], z = corners[c + 3 * k + 2];
      const auto [it, added] =
          index.try_emplace({x, y, z}, static_cast<std::uint32_t>(mesh.vertices.size()));
      if (added) mesh.vertices.push_back(transform.apply(Vec3(Real(x), Real(y), Real(z))));
      tri[k] = it->second;
    }
    mesh.triangles.push_back(tri);
  }
  return mesh;
}

}  // namespace

geometry::TriangleMesh load_mesh_file(const std::string& path, const MeshLoadOptions& options) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) fail_mesh_file(path, "no such file");
  if (!std::filesystem::is_regular_file(path, ec)) fail_mesh_file(path, "not a regular file");
  if (!(options.transform.scale > 0) || !options.transform.rotation.allFinite() ||
      !options.transform.translation.allFinite()) {
    fail_mesh_file(path,
                   "the mesh transform needs a positive scale and finite rotation and translation");
  }
  if (std::string problem = mesh_file_problem(path); !problem.empty())
    fail_mesh_file(path, problem);
  std::vector<float> corners;
  try {
    corners = import_triangle_corners_isolated(path);
  } catch (const MeshImportError& e) {
    fail_mesh_file(path, e.what());
  }
  geometry::TriangleMesh mesh = weld(corners, options.transform);
  if (mesh.triangles.empty()) fail_mesh_file(path, "the file holds no triangles");
  if (!options.run_checks) return mesh;
  if (std::string defect = geometry::first_mesh_defect(mesh, options.checks); !defect.empty())
    fail_mesh_file(path, defect);
  return mesh;
}

}  // namespace imasim::scene
