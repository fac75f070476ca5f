#pragma once
// Tearing of the connective-tissue strands. A strand whose ends have been drawn further apart
// than StrandSet::tear_stretch times their rest distance tears: it lets go at once (all its
// segments' constraints go, as when the cautery divides it) and is marked kStrandTorn, so that
// it dissolves like a divided strand (surgery/strand_cut.hpp, eq. 13) but is not counted as
// divided. Its ends ride on their surfaces, so the measure is the surfaces' separation, not the
// solver's stretch of a segment.
#include <cstdint>
#include <vector>

#include "tissue/tissue_world.hpp"

namespace imasim::tissue {

struct StrandTear {
  std::uint32_t set = 0, strand = 0;
  Real stretch = 0;  // the ends' distance over their rest distance when it tore
};

// Tears every intact strand stretched past its set's tear_stretch; appends them to `torn` and
// returns how many tore. Allocation-free unless one tears.
std::uint32_t tear_overstretched_strands(TissueWorld& world, std::vector<StrandTear>& torn);

}  // namespace imasim::tissue
