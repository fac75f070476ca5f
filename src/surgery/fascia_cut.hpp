#pragma once
// Fascia cutting along the tool's path (paper 2.4.1; SPEC S4). The cutting geometry G_c of one
// step is the quadrilateral the blade sweeps: the blade segment at the step's start moved by
// its displacement over the step. Vertices with |d_i| < epsilon of its plane (d_i the signed
// distance) and inside it lie on the cut; edges whose ends lie on opposite sides are split
// where the plane crosses them, inside the swept area. Local remeshing divides each triangle
// the cut crosses (new vertices V_new, new connectivity E_new); the edges along the cut are
// then separated: each vertex on the cut gets one copy per side (the sectors of its fan that
// the cut edges divide), so the mesh opens along the path. Because each step cuts the area
// swept in that step, the cut follows the tool continuously over many steps; a cut edge whose
// ends cannot separate yet (a slit one edge long in the middle of the sheet) waits until the
// cut grows past it.
//
// Both steps go through tissue/topology_change.hpp, so constraints (removed and added sets),
// colouring, masses, couplings and strand-end bindings stay consistent. A split that would
// leave a piece with an angle below `min_angle` or an area below `min_area` (rest shape) is
// not made; the cut then passes through the nearby vertex instead, or waits for the next step.
#include <cstdint>
#include <vector>

#include "tissue/topology_change.hpp"

namespace imasim::surgery {

// G_c for one step: the blade from `origin` to origin + blade, swept by `motion`.
struct CuttingGeometry {
  Vec3 origin = Vec3::Zero();  // (unit: m)
  Vec3 blade = Vec3::Zero();   // (unit: m)
  Vec3 motion = Vec3::Zero();  // (unit: m)
};

struct FasciaCutParams {
  Real proximity = Real(0.4e-3);  // epsilon (unit: m)
  Real min_angle = Real(0.14);    // smallest angle a new piece may have (unit: rad; ~8 deg)
  Real min_area = Real(1e-8);     // smallest area a new piece may have (unit: m^2; 0.01 mm^2)
};

struct FasciaCutter {
  std::uint32_t mesh = 0;
  // Cut edges (tissue::edge_key) still shared by two triangles, sorted.
  std::vector<std::uint64_t> pending;
  // Vertices the cut has made or passed through, sorted: where a cut left off, the next step's
  // cut continues from them (they count as on the cut when near the new plane).
  std::vector<std::uint32_t> cut_vertices;
};

struct FasciaCutResult {
  tissue::EditStatus status = tissue::EditStatus::applied;
  std::uint32_t edges_split = 0;      // new vertices on crossed edges
  std::uint32_t vertices_copied = 0;  // copies made to separate the sides
  std::uint32_t cut_edges = 0;        // edges along the cut this step
  std::size_t distance_removed = 0, distance_added = 0, dihedral_removed = 0, dihedral_added = 0;
  // The vertices this step made, in the order made (the splits, then the copies): new_vertices[k]
  // is mesh-local vertex first_new_vertex + k, and its parents were made before it. What follows
  // the mesh per vertex (temperature, heart anchors) is carried over from them.
  std::uint32_t first_new_vertex = 0;
  std::vector<tissue::NewVertex> new_vertices;
};

FasciaCutter make_fascia_cutter(std::uint32_t mesh);

// One step of cutting. The world is left consistent whatever happens (a refused edit changes
// nothing: the status says why).
FasciaCutResult cut_fascia(tissue::TissueWorld& world, const FasciaCutParams& params,
                           const CuttingGeometry& cut, FasciaCutter& cutter);

}  // namespace imasim::surgery
