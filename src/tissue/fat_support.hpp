#pragma once
// The fat holds and pushes back: a strand stands for the connective tissue over its
// share A_s of its source face, and that tissue resists being compressed as it resists being
// stretched, E A_s / L over its length L. A strand's chain of distance rows cannot carry this to
// the surfaces it binds (its ends ride on them, kinematic) nor resist compression (it buckles
// when pushed along its length), so each strand is also a column to its base, the chest wall,
// which does not move (physics/support_row.hpp):
// - each vertex of the surface it holds (the fascia, the vessel) gets the columns of the strands
//   bound to its faces, each weighted by its barycentric share there, along their
//   stiffness-weighted mean direction: the layer holds the surface both ways (two-way, eq. 8-9's
//   aim), so it carries its weight and pushes back when it is pressed towards the wall;
// - each interior particle of a strand gets the part of its column below it, E A_s / h (h its
//   height over the base at rest), pushing only (its chain pulls): fat pressed directly, the
//   fascia opened, pushes back too.
// - the layer also holds the surface across its columns (it shears, it does not let the vessel
//   roll away from what presses it): a rigid punch on an elastic half-space resists a sideways
//   push with 2 (1 - nu) / (2 - nu) of its normal stiffness (Mindlin 1949; K. L. Johnson, Contact
//   Mechanics, 1985, sec. 3.6 and 7.2), 2/3 for nearly incompressible fat (nu = 0.5).
// Each row's plane passes through its particle's reference: its rest position, moved by the
// heart's drive where it is anchored (tissue/heart_field.hpp), so the layer holds the tissue
// where the heart's motion puts it, as eq. 9's offsets are measured from it. A strand divided or
// torn carries no column. Rows are gathered before each step, a pushing-only one for a particle
// within reach of its plane.
#include "tissue/tissue_world.hpp"

namespace imasim::tissue {

// How far from its plane a particle gets a row for the step, besides twice its step's travel
// (unit: m): a particle further out cannot reach its column in the step.
inline constexpr Real kSupportReach = Real(1e-3);

// The held surface's stiffness across its columns, a share of that along them (unit: 1):
// 2 (1 - nu) / (2 - nu) at nu = 0.5 (above).
inline constexpr Real kAcrossColumns = Real(2) / Real(3);

// Fills world.state.supports for the next step, in a fixed order. Allocates nothing once the
// world's capacity is reserved (finish_setup).
void gather_fat_supports(TissueWorld& world);

}  // namespace imasim::tissue
