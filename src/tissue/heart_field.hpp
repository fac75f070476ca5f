#pragma once
// The heart acting on the tissue world (SPEC S3 reading), two ways:
//  - a moving collider: after each step no dynamic tissue particle is left inside the heart's
//    current surface (it is put back on the surface, `margin` outside, and loses the velocity
//    component that pointed inwards);
//  - a moving boundary condition: the anchors of the deep tissues follow the heart's
//    displacement from its reference shape (the static phase), attenuated with distance:
//    reference(p) = rest(p) + exp(-d/L) (h_j(t) - h_j(ref)), with h_j the heart vertex nearest
//    p at set-up and d its distance. Kinematic anchors (inverse mass 0) are moved there; the
//    offsets of the couplings (eq. 8-9) are taken from the reference, so the vessel, relaxing by
//    0.8 a step, relaxes towards the moving reference. The maps are built once; nothing is
//    searched for the drive while running. A vertex a cut adds to an anchored mesh is anchored
//    from its parents' anchors (anchor_new_vertices). In static mode the displacement is zero.
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "geometry/uniform_grid.hpp"
#include "physics/chunk_rows.hpp"
#include "physics/contact.hpp"
#include "physics/executor.hpp"
#include "tissue/heart.hpp"
#include "tissue/heart_clearance.hpp"
#include "tissue/tissue_world.hpp"
#include "tissue/topology_change.hpp"

namespace imasim::tissue {

struct HeartField {
  HeartModel model;
  HeartPlayback playback;
  Real margin = Real(0.5e-3);            // kept between tissue and heart (unit: m)
  Real attenuation_length = Real(0.02);  // L (unit: m)
  Real phase = 0;                        // current cycle fraction
  std::vector<Vec3> reference;           // heart at the static phase
  std::vector<Vec3> current;             // heart now
  std::vector<Vec3> previous;            // heart at the start of the step being taken
  std::vector<Vec3> normals;             // of `current`
  struct Anchor {
    std::uint32_t particle = 0, heart_vertex = 0;
    Real weight = 0;  // exp(-d / L)
  };
  std::vector<Anchor> anchors;  // capacity reserved for the anchored meshes' spare vertices
  std::vector<std::uint32_t> anchor_of;  // per particle: its index in `anchors`, or kNone
  std::uint32_t last_contacts = 0;       // particles put back on the surface by the last collide()
  // Collider scratch, sized at set-up.
  std::vector<geometry::Box> boxes;
  geometry::UniformGrid grid;  // over grid_boxes: the boxes grown by a slack (heart_field.cpp)
  std::vector<geometry::Box> grid_boxes;
  Real grid_travel_at = -1;  // clearance.travel when the grid was built; < 0: not built (unit: m)
  std::vector<std::uint32_t> visited;
  std::uint32_t stamp = 0;
  std::vector<std::uint32_t> triangle_component;  // component (LV 0, RV 1) of each triangle
  static constexpr std::uint32_t kNone = 0xffffffffu;
  struct Nearest {  // per component, for the query in progress
    Real distance2 = std::numeric_limits<Real>::infinity();
    std::uint32_t triangle = kNone;
    Vec3 point = Vec3::Zero(), normal = Vec3::Zero();
    Real signed_distance = 0;
  };
  std::vector<Nearest> nearest;
  HeartClearance clearance;  // what the particles' last searches proved (heart_clearance.hpp)
  // A parallel pass's scratch, one per part of the executor: its own `nearest`, `visited` and
  // `stamp`, the counts it adds to `clearance` when the pass ends, and the particles it put out
  // of the heart (collide_with_heart).
  struct alignas(64) PartQuery {  // a cache line apart: parts count and stamp at once
    std::vector<Nearest> nearest;
    std::vector<std::uint32_t> visited;
    std::uint32_t stamp = 0;
    std::uint64_t searched = 0, skipped = 0;
    std::uint32_t put_out = 0;
  };
  std::vector<PartQuery> part_queries;
  physics::ChunkRows<physics::ContactRow> contact_chunks;  // gather_heart_contacts' rows
};

// Projection passes per particle in collide_with_heart (where the ventricles overlap, leaving
// one can enter the other).
inline constexpr int kHeartCollisionPasses = 4;

// Builds the field; the heart starts at playback.phase_at(0).
HeartField make_heart_field(const HeartModel& model, const HeartPlayback& playback);

// Drives the particles of the given mesh objects and strand sets (interior particles) with the
// heart (see above). Call at set-up, after the world is built.
void add_heart_anchors(HeartField& heart, TissueWorld& world,
                       const std::vector<std::uint32_t>& meshes,
                       const std::vector<std::uint32_t>& strand_sets);

// After a topology change of world.meshes[mesh] that made `vertices` (new vertex k is mesh-local
// first_new_vertex + k, its parents made before it): each new vertex whose parents are anchored
// is anchored too, to the heart vertex of its nearer parent (a's for t <= 1/2) with the weight
// (1 - t) w_a + t w_b (a copy: its parent's anchor), and put where that anchor drives it now
// (reference; position too if kinematic). O(new vertices), no search; does not allocate while
// the mesh's spare vertices last (reserved by add_heart_anchors). Call it right after the cut.
void anchor_new_vertices(HeartField& heart, TissueWorld& world, std::uint32_t mesh,
                         std::uint32_t first_new_vertex, std::span<const NewVertex> vertices);

// Moves the heart to the cycle phase at `time_s` and the anchors with it.
void advance_heart(HeartField& heart, TissueWorld& world, double time_s);

// Puts dynamic particles found inside the heart back on its surface; returns how many. A
// particle is looked for within `search` of the surface plus however far it moved since
// `previous` (its position before this step): the heart moves < 0.2 mm per step and nothing is
// left inside after a step, so nothing can have got deeper than that. At set-up, where tissue may
// start deep inside the heart, pass the current positions as `previous` and a larger search.
inline constexpr Real kHeartStepSearch = Real(0.002);  // (unit: m)
// `inside` is how far past the margin band a particle must be to count: 0 at set-up (keep the
// margin), the margin itself after a step whose contacts keep it (only a particle actually inside
// the surface was missed; the contact planes approximate the faceted surface within the band).
// In parallel over fixed chunks of the particles (each particle's answer is its own): the same
// bits on any thread count.
std::uint32_t collide_with_heart(HeartField& heart, physics::Particles& particles,
                                 std::span<const Vec3> previous, const physics::Executor& exec,
                                 Real search = kHeartStepSearch, Real inside = 0);
// On the calling thread alone.
std::uint32_t collide_with_heart(HeartField& heart, physics::Particles& particles,
                                 std::span<const Vec3> previous, Real search = kHeartStepSearch,
                                 Real inside = 0);

// Fills heart.nearest: per component (LV, RV) the nearest surface point to p within `search`,
// its triangle, interpolated normal and signed distance (triangle kNone where none is that near).
void nearest_per_component(HeartField& heart, const Vec3& p, Real search);

// nearest_per_component for particle `particle` (of `particles`) at its query point p: answered
// from heart.clearance without searching when that proves nothing within `search`, else searched
// (as far as clearance.reach farther when the particle was clear last time, to prove it clear
// for the steps to come). The same answer as nearest_per_component(heart, p, search).
void nearest_per_component_of_particle(HeartField& heart, std::uint32_t particle,
                                       std::size_t particles, const Vec3& p, Real search);
// The same for a parallel pass: the answer in query.nearest, the count in query. Call
// prepare_heart_queries first, on one thread.
void nearest_per_component_of_particle(HeartField& heart, HeartField::PartQuery& query,
                                       std::uint32_t particle, const Vec3& p, Real search);
// Readies a parallel pass over `particles` particles on `exec`: the clearance sized for them, a
// query for every part (allocates only the first time, or when either grows).
void prepare_heart_queries(HeartField& heart, std::size_t particles, const physics::Executor& exec);
// Adds the parts' counts to heart.clearance after a parallel pass.
void finish_heart_queries(HeartField& heart);

// Signed distance of p from the heart, the union of its closed surfaces, near p: inside any of
// them, minus the depth in the one it is deepest in; outside all, the distance to the nearest;
// +infinity when no heart triangle lies within `search` (unit: m).
Real heart_signed_distance(HeartField& heart, const Vec3& p, Real search);

// The velocity of the heart's surface at its point nearest p (within `search`) now, at the
// phase of the last advance_heart: the time derivative of the playback (heart_vertex_rate times
// the cycles per second) mixed with the nearest point's barycentric weights (unit: m/s). Zero
// when no surface lies within `search` or the heart is still. The local model of the haptic loop
// carries the heart's contact plane with it between physics steps.
Vec3 heart_surface_velocity(HeartField& heart, const Vec3& p, Real search);

}  // namespace imasim::tissue
