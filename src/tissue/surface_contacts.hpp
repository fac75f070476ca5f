#pragma once
// Contacts of the tissue with the heart and the chest wall, gathered once per step for the solver
// (physics/contact.hpp), so that they are constraints inside every substep rather than a
// correction after it (SPEC S1).
//  - Heart: for each dynamic particle whose predicted position x + v dt comes within `search` of
//    a ventricle (LV, RV: the heart is their union), one plane per ventricle at the nearest point
//    of its surface at the step's end, with the interpolated normal; point0 is the same
//    barycentric point on the heart at the step's start, so the plane moves with the wall's own
//    velocity (friction acts on the relative motion).
//  - Chest wall: the cavity's cylinder (the wall's inner surface) from inside: particles within
//    `search` of it get the tangent plane, normal towards the axis; the wall does not move.
//  - Cavity floor: the plane y = floor_y (the collapsed lung and the pericardium under the
//    field), normal +y: particles within `search` of it from above get it; it does not move.
#include <cstdint>

#include <span>

#include "geometry/tube.hpp"
#include "physics/chunk_rows.hpp"
#include "physics/contact.hpp"
#include "physics/particles.hpp"
#include "tissue/heart_field.hpp"

namespace imasim::tissue {

// Tags of the surfaces' contact rows.
inline constexpr std::uint32_t kHeartContact = 1, kWallContact = 2, kFloorContact = 3;

struct SurfaceContactParams {
  Real search = Real(0.002);  // beyond the predicted motion (unit: m)
  // The epicardium and the pleura are wet serous surfaces: low friction (ours).
  Real heart_static_friction = Real(0.1), heart_kinetic_friction = Real(0.05);
  Real wall_static_friction = Real(0.3), wall_kinetic_friction = Real(0.2);
  // The lung's pleura and the pericardium are wet serous surfaces too (ours, as the heart's).
  Real floor_static_friction = Real(0.1), floor_kinetic_friction = Real(0.05);
};

// Appends the heart's contacts (margin: heart.margin); heart.previous and heart.current are the
// step's start and end shapes (advance_heart). dt: the step (unit: s).
void gather_heart_contacts(HeartField& heart, const physics::Particles& particles, Real dt,
                           const SurfaceContactParams& params, physics::ContactSet& out);
// The same in parallel over fixed chunks of the particles: the same rows in the same order on
// any thread count.
void gather_heart_contacts(HeartField& heart, const physics::Particles& particles, Real dt,
                           const SurfaceContactParams& params, physics::ContactSet& out,
                           const physics::Executor& exec);

// Appends the chest wall's contacts (margin 0).
void gather_wall_contacts(const geometry::CylinderPatchSpec& wall,
                          const physics::Particles& particles, Real dt,
                          const SurfaceContactParams& params, physics::ContactSet& out);

// Appends the cavity floor's contacts (margin 0): the plane y = floor_y (unit: m), normal +y.
void gather_floor_contacts(Real floor_y, const physics::Particles& particles, Real dt,
                           const SurfaceContactParams& params, physics::ContactSet& out);

// Each chunk's rows of the wall's and the floor's parallel gathering (kept: no allocation once
// sized).
struct WallAndFloorChunks {
  physics::ChunkRows<physics::ContactRow> wall, floor;
};

// gather_wall_contacts then gather_floor_contacts, each in parallel over fixed chunks of the
// particles: the same rows in the same order on any thread count.
void gather_wall_and_floor_contacts(const geometry::CylinderPatchSpec& wall, Real floor_y,
                                    const physics::Particles& particles, Real dt,
                                    const SurfaceContactParams& params, physics::ContactSet& out,
                                    const physics::Executor& exec, WallAndFloorChunks& chunks);

// Removes the rows of `out` from row `first` on whose particle is flagged in `held`: tissue the
// forceps hold goes where the jaws take it, and the jaws are kept out of these surfaces (the
// instruments' stops). A held particle pushed out by a surface while the grasp pulls it in would
// be two rigid rows fighting, settled by the solver's splitting instead of the physics (the
// forceps pulling fat against the heart read half the force of a finer solve). No allocation.
void drop_held_rows(physics::ContactSet& out, std::size_t first,
                    std::span<const std::uint8_t> held);

}  // namespace imasim::tissue
