#pragma once
// Fragments a cut frees (SPEC S4 reading). The hook's cuts can part a sliver of one or two
// triangles from the sheet. Held by nothing, such a sliver falls through the cavity until the
// heart or the far chest wall catches it; at the electrode it would be vaporised, as the tissue
// of the cut itself is. vaporise_free_fragments takes each small free piece of the fascia out of
// the mesh (tissue::remove_mesh_triangles). A piece is a set of triangles joined through shared
// vertices; it is free when none of its vertices is fixed, held by the forceps or moved by a
// coupling; small when its rest area is at most `max_area`. The largest piece (the sheet) always
// stays. Strands do not hold a piece: their ends follow the surface they are bound to and pull
// nothing (tissue_world.hpp); a strand ending on a removed piece keeps its end on the nearest
// point of the sheet. The surgical session calls it after each step that cut the fascia or
// released the forceps (docs/surgery.md).
#include <cstdint>

#include "surgery/fascia_cut.hpp"

namespace imasim::surgery {

struct FragmentParams {
  // Largest free piece vaporised, by rest area (unit: m^2): the electrode's omega x omega
  // cutting square (eq. 12, omega = 4 mm), the most the energised tip covers at once. The slivers
  // a cut frees are pieces of triangles it divided (0.09-4.3 mm^2 in the example session); a
  // harvest also frees pieces of two or three of the default grid's 7 mm^2 triangles.
  Real max_area = Real(16e-6);
};

struct FragmentRemoval {
  tissue::EditStatus status = tissue::EditStatus::applied;
  std::uint32_t fragments = 0;  // pieces removed
  std::uint32_t triangles = 0;  // their triangles
  Real area = 0;                // their rest area (unit: m^2)
};

// Removes the small free pieces of the cutter's mesh (see above) and forgets them in the
// cutter's state (its pending edges and the vertices on its cut).
FragmentRemoval vaporise_free_fragments(tissue::TissueWorld& world, const FragmentParams& params,
                                        FasciaCutter& cutter);

}  // namespace imasim::surgery
