#pragma once
// Where the coarse band's further sweeps are needed. Its first sweep visits every row; the
// further ones (SolverParams::coarse_sweeps) matter only where a row pulls against the rows that
// act on the band from outside: the tools' contacts, the particles the proxies hold and the fat's
// columns. There one sweep leaves the band soft (the grasp's pull, docs/physics.md), while the
// rest of it, at rest or carried by its surfaces, reads the same after one sweep as after three.
// So the further sweeps visit the rows of such particles only, with the band's contacts, follow
// rows and held particles as before (all of them: they are few). Reaching further, to the rows
// 2 or 4 rows away, was measured and read 6 % over the finer solve as the jaws close (a patch
// converged against a boundary swept once acts stiff; docs/physics.md).
#include <cstdint>
#include <vector>

#include "physics/constraint_system.hpp"

namespace imasim::physics {

struct State;

// A row of a coloured store by its group and its place there (rows do not move within a step).
struct RowRef {
  std::uint32_t group = 0, position = 0;
};

// The further sweeps' rows of one band, in projection order (colours, then the overflow group).
struct ActiveRows {
  std::vector<std::uint8_t> touched;  // per particle: acted on from outside this step
  std::vector<RowRef> distance, attachment;
  std::size_t distance_count = 0, attachment_count = 0;
};

// Sizes the buffers for the state's particles and rows (allocates only when they grew).
void prepare_active_rows(const State& state, ActiveRows& active);

// Finds `band`'s distance and attachment rows with a particle in one of its contacts, held
// particles or support rows. Those rows must be ordered by band (step.cpp's order_rows_by_band).
void find_active_rows(State& state, std::uint32_t band, ActiveRows& active);

}  // namespace imasim::physics
