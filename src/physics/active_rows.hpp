#pragma once
// Where the coarse band's further sweeps are needed. Its first sweep visits every row; the
// further ones (SolverParams::coarse_sweeps) matter only where a row pulls against the rows that
// act on the band from outside: the tools' contacts, the particles the proxies hold and the fat's
// columns. There one sweep leaves the band soft (the grasp's pull, docs/physics.md), while the
// rest of it, at rest or carried by its surfaces, reads the same after one sweep as after three.
// So the further sweeps visit the rows within kActiveRings rows of such a particle, with the
// contacts, follow rows and held particles as before (all of them: they are few).
#include <cstdint>
#include <vector>

#include "physics/constraint_system.hpp"

namespace imasim::physics {

struct State;

// How far from a seed particle (one touched from outside) the further sweeps reach, in rows:
// 1, the rows of the seeds themselves. Measured on the grasp's pull (docs/physics.md): within
// 2 % of 256 x 4 in every half-second with 1, while 2 and 4 rings read 6 % over it as the jaws
// close (the sweeps converge a patch against a boundary swept once, which then acts stiff).
inline constexpr std::uint32_t kActiveRings = 1;

// A row of a coloured store by its group and its place there (rows do not move within a step).
struct RowRef {
  std::uint32_t group = 0, position = 0;
};

// The further sweeps' rows of one band, in projection order (colours, then the overflow group).
struct ActiveRows {
  std::vector<std::uint8_t> ring;  // per particle: 0 = not reached, else 1 + rows from a seed
  std::vector<RowRef> distance, attachment;
  std::size_t distance_count = 0, attachment_count = 0;
};

// Sizes the buffers for the state's particles and rows (allocates only when they grew).
void prepare_active_rows(const State& state, ActiveRows& active);

// Finds `band`'s rows within kActiveRings of its contacts', held particles' and support rows'
// particles. The rows of contacts, held particles and supports must be ordered by band
// (step.cpp's order_rows_by_band). Deterministic: rings grow one row at a time, in row order.
void find_active_rows(State& state, std::uint32_t band, ActiveRows& active);

}  // namespace imasim::physics
