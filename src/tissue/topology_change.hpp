#pragma once
// One topology change of a simulated mesh object (fascia cutting, paper 2.4.1): new vertices,
// triangles replaced and added, applied to everything that depends on the mesh at once:
//   - particles: each new vertex takes a reserved particle (MeshObject::particle_capacity) with
//     current position, rest position, velocity and heart-drive reference interpolated from its
//     parents, x' = (1 - t) x_a + t x_b (a copy when a == b);
//   - mass: eq. 5 is kept, every dynamic vertex carries M_total / n for the new vertex count n,
//     so the object's mass stays M_total exactly (fixed vertices stay fixed; a vertex between
//     two fixed parents is fixed);
//   - constraints: on every edge the change touches, the distance (eq. 2) and dihedral (eq. 3)
//     constraints are removed and those the new mesh needs are added, their rest values taken
//     from the rest positions; the removed and added handles are reported. The coloured store
//     keeps its colouring valid through removal and greedy addition;
//   - mappings: strand ends and visual vertices bound to a replaced triangle are re-bound to the
//     piece of it that holds their rest point; coupling pairs whose source vertex was copied
//     follow the copy on their side of the cut;
//   - the edge index (faces and constraints per edge) and the vertex normals.
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "geometry/mesh_checks.hpp"
#include "tissue/tissue_world.hpp"

namespace imasim::tissue {

struct NewVertex {
  std::uint32_t a = 0, b = 0;  // parent vertices (mesh-local); a == b makes a copy of a
  Real t = 0;                  // weight of b
};

struct MeshEdit {
  // New vertex k gets mesh-local index particle_count + k.
  std::vector<NewVertex> vertices;
  // Existing triangles given new vertex indices (the same winding).
  std::vector<std::pair<std::uint32_t, geometry::Triangle>> replaced;
  struct Added {
    geometry::Triangle triangle;
    std::uint32_t origin = 0;  // the triangle (before the edit) it was cut from
  };
  std::vector<Added> added;

  bool empty() const { return vertices.empty() && replaced.empty() && added.empty(); }
};

enum class EditStatus : std::uint8_t { applied, out_of_capacity, invalid };

struct TopologyChange {
  EditStatus status = EditStatus::applied;
  std::string message;                 // why an edit was refused
  std::uint32_t first_new_vertex = 0;  // mesh-local
  std::vector<physics::DistanceHandle> distance_removed, distance_added;
  std::vector<physics::DihedralHandle> dihedral_removed, dihedral_added;
};

// Builds the edge index of a mesh object from its triangles and the constraints on its edges.
// Set-up (add_mesh_object calls it for meshes with spare vertices).
void index_mesh_edges(TissueWorld& world, std::uint32_t mesh);

// Applies `edit` to world.meshes[mesh] (see above); the world is unchanged when it is refused
// (no spare particles left, or an index out of range). The caller keeps the mesh a manifold.
TopologyChange apply_mesh_edit(TissueWorld& world, std::uint32_t mesh, const MeshEdit& edit);

// Takes the triangles `triangles` (indices, any order) out of world.meshes[mesh]: a fragment the
// cautery vaporises. Their edges' constraints are removed and those still bordering a triangle
// rebuilt as boundary edges; the survivors keep their order and every index to them (edge index,
// strand ends, visual bindings) is renumbered; a binding on a removed triangle moves to the
// nearest point of a surviving one, found where the mesh is now. Vertices left in no triangle are
// retired: fixed (inverse mass 0) where they are, at rest, in no constraint, and the coupling pairs
// they were the source of are dropped. Refused (the world unchanged) when a triangle does not
// exist, every triangle would go, or a retired vertex is held by an instrument or is a coupling's
// destination.
TopologyChange remove_mesh_triangles(TissueWorld& world, std::uint32_t mesh,
                                     std::span<const std::uint32_t> triangles);

// The first broken invariant of a mesh object that changes topology, or "": the mesh checks
// (indices, degenerate triangles by `options`' smallest area and angle on the rest positions,
// manifold; a vertex in no triangle is retired: fixed and at rest), the edge index matches the
// triangles, every edge has exactly its distance constraint and every interior edge its dihedral
// with the right four particles, no constraint, coupling or binding refers to a vertex or triangle
// that does not exist, eq. 5's masses, finite values, and the solver's own checks (colouring,
// ranges).
std::string first_topology_defect(TissueWorld& world, std::uint32_t mesh,
                                  const geometry::MeshCheckOptions& options);

// The rest configuration of a mesh object as a TriangleMesh (mesh-local vertices).
geometry::TriangleMesh rest_mesh(const TissueWorld& world, const MeshObject& mesh);

}  // namespace imasim::tissue
