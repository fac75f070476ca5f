#include "scene/heart_series.hpp"

#include <numeric>

#include <sstream>
#include "geometry/mesh_repair.hpp"

namespace imasim::scene {

namespace {

// The size of a heart after the file's transform: a mouse heart is about 6 mm long, a human one
// 12 cm, and the simulated cavity about 30 cm across. Outside these the mesh_scale is wrong
// (metres read as millimetres, or the reverse) and the run would be meaningless or never end.
constexpr Real kMinHeartSize = Real(0.005), kMaxHeartSize = Real(0.5);  // (unit: m)

// The largest extent of the mesh's bounding box against the limits above.
void check_heart_size(const std::string& path, const geometry::TriangleMesh& mesh) {
  Vec3 lo = mesh.vertices.front(), hi = lo;
  for (const Vec3& v : mesh.vertices)
    lo = lo.cwiseMin(v), hi = hi.cwiseMax(v);
  const Real size = (hi - lo).maxCoeff();
  if (size >= kMinHeartSize && size <= kMaxHeartSize) return;
  std::ostringstream s;
  s << "the heart is " << size << " m across after heart.mesh_scale; expected " << kMinHeartSize
    << " to " << kMaxHeartSize << " m (is the mesh_scale right for the file's unit? 0.001: mm)";
  fail_mesh_file(path, s.str());
}

}  // namespace

tissue::HeartModel load_heart_series(const HeartSeriesSpec& spec, std::vector<std::string>* notes) {
  if (spec.phase_files.size() < 2) {
    throw MeshFileError("heart phase series: at least two phase files are needed, got " +
                        std::to_string(spec.phase_files.size()));
  }
  MeshLoadOptions options;
  options.transform = spec.transform;
  options.run_checks = false;  // repaired first (segmentations are open, with collapsed poles)
  std::vector<geometry::TriangleMesh> phases;
  std::size_t collapsed = 0;
  for (const std::string& path : spec.phase_files) {
    phases.push_back(load_mesh_file(path, options));
    collapsed = geometry::drop_collapsed_triangles(phases.back());
    if (phases.back().triangles.empty())
      fail_mesh_file(path, "every triangle collapsed when welded");
    check_heart_size(path, phases.back());
    const geometry::TriangleMesh& first = phases.front();
    const geometry::TriangleMesh& mesh = phases.back();
    if (mesh.vertex_count() != first.vertex_count() ||
        mesh.triangle_count() != first.triangle_count()) {
      fail_mesh_file(
          path, "phase " + std::to_string(phases.size() - 1) + " has " +
                    std::to_string(mesh.vertex_count()) + " vertices and " +
                    std::to_string(mesh.triangle_count()) + " triangles, the first phase " +
                    std::to_string(first.vertex_count()) + " and " +
                    std::to_string(first.triangle_count()) +
                    " (after welding coincident vertices and dropping collapsed triangles): one "
                    "topology is needed");
    }
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
      if (mesh.triangles[t] != first.triangles[t])
        fail_mesh_file(path, "triangle " + std::to_string(t) + " differs from the first phase's");
    }
  }
  if (collapsed > 0 && notes != nullptr) {
    notes->push_back("heart phase files: " + std::to_string(collapsed) +
                     " triangles per phase collapsed when coincident vertices were welded (a "
                     "repeated vertex, no area) and were dropped");
  }
  // An open surface (a ventricle open at its valve plane) is capped: the collider needs an inside.
  const geometry::BoundaryLoops boundary = geometry::boundary_loops(phases.front());
  if (!boundary.defect.empty()) fail_mesh_file(spec.phase_files.front(), boundary.defect);
  if (!boundary.loops.empty()) {
    std::size_t added = 0;
    for (geometry::TriangleMesh& phase : phases)
      added = geometry::cap_boundary_loops(phase, boundary);
    if (notes != nullptr) {
      notes->push_back("heart phase files: the surface is open; " +
                       std::to_string(boundary.loops.size()) +
                       " boundary loops were closed with a cap of " + std::to_string(added) +
                       " triangles around each loop's centre, as \"close holes\" does");
    }
  }
  geometry::MeshCheckOptions checks;
  checks.require_closed = true;
  for (std::size_t k = 0; k < phases.size(); ++k) {
    if (std::string defect = geometry::first_mesh_defect(phases[k], checks); !defect.empty())
      fail_mesh_file(spec.phase_files[k], defect);
  }

  // Components as contiguous vertex and triangle ranges, in order of their first triangle.
  const geometry::TriangleMesh& first = phases.front();
  std::vector<std::uint32_t> component;
  const std::uint32_t count = geometry::triangle_components(first, component);
  std::vector<std::uint32_t> triangle_order(first.triangle_count());
  std::iota(triangle_order.begin(), triangle_order.end(), 0u);
  std::stable_sort(triangle_order.begin(), triangle_order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return component[a] < component[b]; });
  constexpr std::uint32_t kUnset = ~0u;
  std::vector<std::uint32_t> new_index(first.vertex_count(), kUnset), old_index;
  tissue::HeartModel heart;
  for (std::uint32_t c = 0, k = 0; c < count; ++c) {
    heart.component_start.push_back(static_cast<std::uint32_t>(old_index.size()));
    heart.component_triangle_start.push_back(k);
    for (; k < triangle_order.size() && component[triangle_order[k]] == c; ++k) {
      geometry::Triangle tri = first.triangles[triangle_order[k]];
      for (std::uint32_t& v : tri) {
        if (new_index[v] == kUnset) {
          new_index[v] = static_cast<std::uint32_t>(old_index.size());
          old_index.push_back(v);
        }
        v = new_index[v];
      }
      heart.topology.triangles.push_back(tri);
    }
  }
  heart.component_start.push_back(static_cast<std::uint32_t>(old_index.size()));
  heart.component_triangle_start.push_back(static_cast<std::uint32_t>(triangle_order.size()));

  for (std::size_t k = 0; k < phases.size(); ++k) {
    std::vector<Vec3>& frame = heart.keyframes.emplace_back();
    for (std::uint32_t v : old_index)
      frame.push_back(phases[k].vertices[v]);
    for (std::uint32_t c = 0; c < count; ++c) {
      if (!(tissue::component_volume(heart, frame, c) > 0)) {
        fail_mesh_file(spec.phase_files[k],
                       "surface " + std::to_string(c) +
                           " encloses no positive volume: its triangles face inwards");
      }
    }
  }
  heart.topology.vertices = heart.keyframes.front();
  return heart;
}

}  // namespace imasim::scene
