#pragma once
// One world, many tissue objects: every object's particles live in one physics State, so a
// constraint may join particles of different objects (strands, attachments, grasping), while
// each object keeps its own parameters (mass, gravity, damping, materials).
#include <cstdint>
#include <string>
#include <unordered_map>
#include <vector>

#include "geometry/edge_adjacency.hpp"
#include "geometry/surface_binding.hpp"
#include "geometry/triangle_mesh.hpp"
#include "physics/mesh_constraints.hpp"
#include "physics/model.hpp"
#include "physics/state.hpp"
#include "tissue/coupling.hpp"

namespace imasim::tissue {

// Per edge of a mesh that can change topology: its faces and its constraints (eq. 2, eq. 3).
struct EdgeRecord {
  std::uint32_t faces[2] = {geometry::kNoFace, geometry::kNoFace};
  physics::DistanceHandle distance;
  physics::DihedralHandle dihedral;  // null on a boundary edge
};

// Key of the undirected edge (a, b) of a mesh (mesh-local vertex indices).
inline std::uint64_t edge_key(std::uint32_t a, std::uint32_t b) {
  return a < b ? (std::uint64_t(a) << 32) | b : (std::uint64_t(b) << 32) | a;
}

// A simulated triangle surface: mesh vertex v is particle first_particle + v.
struct MeshObject {
  std::string name;
  physics::ObjectId object = 0;
  std::uint32_t first_particle = 0;
  std::uint32_t particle_count = 0;
  std::vector<geometry::Triangle> triangles;  // mesh-local vertex indices
  std::vector<Vec3> normals;                  // per vertex, refreshed every step
  // Topology changes (tissue/topology_change.hpp). Particles first_particle + particle_count up
  // to first_particle + particle_capacity are reserved for the vertices that cutting adds: fixed,
  // in no constraint, on no triangle until used. The edge index (faces and constraints of each
  // edge) is kept only for meshes with spare capacity; it is looked up, never iterated.
  std::uint32_t particle_capacity = 0;
  // Topology changes applied so far: what was built from the mesh (the implicit fascia's solver)
  // knows by it when to rebuild.
  std::uint32_t topology_revision = 0;
  // false: another solver holds the edges (the implicit fascia), so the edge index's rows may be
  // empty; a cut still adds rows, which that solver takes out again.
  bool rows_in_xpbd = true;
  Real total_mass = 0;  // M_total of eq. 5 (unit: kg)
  physics::MaterialId stretch_material = 0, bend_material = 0;
  // Whether rows scale the materials' compliance by their rest geometry (a membrane).
  physics::CompliancePerRow per_row = physics::CompliancePerRow::material;
  std::unordered_map<std::uint64_t, EdgeRecord> edges;
};

// A fine display mesh that follows a coarse MeshObject (SPEC S2 multi-resolution).
struct VisualMesh {
  std::uint32_t source_mesh = 0;  // index into TissueWorld::meshes
  std::vector<geometry::Triangle> triangles;
  std::vector<geometry::SurfaceBinding> bindings;  // one per fine vertex
  std::vector<Vec3> positions;                     // refreshed every step (unit: m)
};

// StrandSet::cut: intact, divided by the cautery (eq. 10-12), or torn (strand_tear.hpp).
inline constexpr std::uint8_t kStrandIntact = 0, kStrandDivided = 1, kStrandTorn = 2;

// Connective-tissue strands between two mesh objects (2.3.4). Strand s owns particles
// first_particle + s * (segments + 1) ... + segments; its first and last particles are its ends,
// kinematic (inverse mass 0) and placed on their surfaces every step through the bindings.
struct StrandSet {
  std::string name;
  physics::ObjectId object = 0;
  std::uint32_t mesh_a = 0, mesh_b = 0;
  std::uint32_t segments = 0;  // n
  std::uint32_t first_particle = 0;
  std::uint32_t strand_count = 0;
  std::vector<geometry::SurfaceBinding> end_a, end_b;  // per strand, on mesh_a and mesh_b
  std::vector<std::uint32_t> face_a;                   // source face of each strand on mesh_a
  std::vector<Real> diameter;  // per strand particle, for drawing (unit: m); 0 = removed
  // Cutting (surgery/strand_cut.hpp) and tearing (strand_tear.hpp): the distance constraint of
  // each segment (strand * n + k, stale once removed) and each strand's state (kStrandIntact,
  // kStrandDivided, kStrandTorn); a strand that is not intact has let go and dissolves.
  std::vector<physics::DistanceHandle> segment_constraint;
  std::vector<std::uint8_t> cut;
  // A strand tears when its ends are further apart than this many times their rest distance.
  Real tear_stretch = 0;
  // XSPH smoothing (SPEC S2): the neighbours at rest, each pair once from its lower index (over
  // the set's particles): pairs pair_start[k] .. pair_start[k + 1] are (k, pair_upper[p]) in
  // ascending order, and pair_lower[p] = k (for passes over all pairs); the smoothing
  // coefficient in [0, 1].
  std::vector<std::uint32_t> pair_start, pair_lower, pair_upper;
  // The same pairs seen from their upper particle: incoming_pair[incoming_start[k] ..
  // incoming_start[k + 1]] are the pairs (j, k), j < k, in ascending order (so a particle can
  // gather its sums in the order a pass over the pairs would scatter them).
  std::vector<std::uint32_t> incoming_start, incoming_pair;
  Real xsph_coefficient = 0;
  Real xsph_radius = 0;  // (unit: m)
  // The fat a strand stands for as a column to its base, which does not move (fat_support.hpp):
  // per strand, its stiffness E A_s / L (unit: N/m) and its direction at rest, from its end on
  // mesh_b to its end on mesh_a (unit vector). Empty when the set has no columns.
  std::vector<Real> column_stiffness;
  std::vector<Vec3> column_direction;

  std::uint32_t particle_count() const { return strand_count * (segments + 1); }
  std::uint32_t particle(std::uint32_t strand, std::uint32_t k) const {
    return first_particle + strand * (segments + 1) + k;
  }
};

struct TissueWorld {
  physics::Model model;
  physics::State state;
  std::vector<MeshObject> meshes;
  std::vector<VisualMesh> visuals;
  std::vector<StrandSet> strands;
  std::vector<OffsetCoupling> couplings;
  // Per particle: where its offsets are measured from (eq. 8-9): the rest position, moved by
  // boundary conditions such as the heart's drive (heart_field.hpp).
  std::vector<Vec3> reference;
  std::vector<Vec3> xsph_scratch;  // velocities being smoothed, sized at set-up
  std::vector<Real> xsph_kernel;   // W_ij per neighbour pair while smoothing, sized at set-up
  std::vector<Real> xsph_share;    // each pair's exchange weight while smoothing, sized at set-up
  std::vector<Real> xsph_weight;   // sum_j W_ij per particle while smoothing, sized at set-up
  // Per particle: held by an instrument (grasped). Held particles follow the jaws through their
  // attachments, not the couplings (eq. 8-9), so a grasp is not undone every step.
  std::vector<std::uint8_t> held;
  // Per particle, refreshed each step from `held`: of a strand a held particle belongs to. Such
  // fat drives the surfaces it is coupled to (eq. 9's beta, coupling.hpp).
  std::vector<std::uint8_t> manipulated;
  // Per particle, while the fat's columns are gathered (fat_support.hpp): the stiffness of the
  // columns under it (unit: N/m) and their stiffness-weighted direction (unit: N/m). Sized at
  // set-up, left zero.
  std::vector<Real> support_stiffness;
  std::vector<Vec3> support_direction;
};

}  // namespace imasim::tissue
