#pragma once
// The fat holds and pushes back (issue 41): a strand stands for the connective tissue over its
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
// Each row's plane passes through its particle's rest position. A strand divided or torn carries
// no column. Rows are gathered before each step, a pushing-only one for a particle within reach
// of its plane.
#include "tissue/tissue_world.hpp"

namespace imasim::tissue {

// How far from its plane a particle gets a row for the step, besides twice its step's travel
// (unit: m): a particle further out cannot reach its column in the step.
inline constexpr Real kSupportReach = Real(1e-3);

// Fills world.state.supports for the next step, in a fixed order. Allocates nothing once the
// world's capacity is reserved (finish_setup).
void gather_fat_supports(TissueWorld& world);

}  // namespace imasim::tissue
