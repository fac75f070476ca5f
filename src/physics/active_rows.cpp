#include "physics/active_rows.hpp"

#include <algorithm>

#include "physics/state.hpp"

namespace imasim::physics {

namespace {

// Marks ring r + 1 on the particles of every row of `band` that touches ring r.
template <class Row>
void grow_ring(const ColouredStore<Row>& store, std::uint32_t band, std::uint8_t r,
               std::vector<std::uint8_t>& ring) {
  using Store = ColouredStore<Row>;
  const auto groups = store.groups();
  auto visit = [&](const typename Store::Group& g) {
    for (const Row& row : g.rows) {
      bool touches = false;
      for (std::uint32_t p : row.particles())
        touches = touches || ring[p] == r;
      if (!touches) continue;
      for (std::uint32_t p : row.particles())
        if (ring[p] == 0) ring[p] = std::uint8_t(r + 1);
    }
  };
  for (std::uint32_t g = store.band_first(band); g < store.band_end(band); ++g)
    visit(groups[g]);
  visit(groups[Store::overflow_group(band)]);
}

// The rows of `band` with a particle reached, in projection order.
template <class Row>
std::size_t collect(const ColouredStore<Row>& store, std::uint32_t band,
                    const std::vector<std::uint8_t>& ring, std::vector<RowRef>& out) {
  using Store = ColouredStore<Row>;
  const auto groups = store.groups();
  std::size_t n = 0;
  auto visit = [&](std::uint32_t g) {
    const auto& rows = groups[g].rows;
    for (std::size_t k = 0; k < rows.size(); ++k) {
      bool reached = false;
      for (std::uint32_t p : rows[k].particles())
        reached = reached || (ring[p] != 0 && ring[p] <= kActiveRings);
      if (reached) out[n++] = {g, static_cast<std::uint32_t>(k)};
    }
  };
  for (std::uint32_t g = store.band_first(band); g < store.band_end(band); ++g)
    visit(g);
  visit(Store::overflow_group(band));
  return n;
}

}  // namespace

void prepare_active_rows(const State& state, ActiveRows& active) {
  if (active.ring.size() < state.particles.size()) active.ring.resize(state.particles.size());
  const std::size_t d = state.constraints.distance.size();
  const std::size_t a = state.constraints.attachment.size();
  if (active.distance.size() < d) active.distance.resize(d);
  if (active.attachment.size() < a) active.attachment.resize(a);
}

void find_active_rows(State& state, std::uint32_t band, ActiveRows& active) {
  std::fill(active.ring.begin(), active.ring.end(), std::uint8_t(0));
  const StepScratch& s = state.scratch;
  const std::size_t contacts_first = band == 0 ? 0 : s.contact_split;
  const std::size_t contacts_end = band == 0 ? s.contact_split : state.contacts.rows.size();
  for (std::size_t k = contacts_first; k < contacts_end; ++k)
    active.ring[state.contacts.rows[k].particle] = 1;
  const std::size_t held_first = band == 0 ? 0 : s.body_attachment_split;
  const std::size_t held_end = band == 0 ? s.body_attachment_split : state.body_attachments.size();
  for (std::size_t k = held_first; k < held_end; ++k)
    active.ring[state.body_attachments[k].particle] = 1;
  const std::size_t supports_first = band == 0 ? 0 : s.support_split;
  const std::size_t supports_end = band == 0 ? s.support_split : state.supports.size();
  for (std::size_t k = supports_first; k < supports_end; ++k)
    active.ring[state.supports[k].particle] = 1;
  const ConstraintSystem& cs = state.constraints;
  for (std::uint8_t r = 1; r < kActiveRings; ++r) {
    grow_ring(cs.distance, band, r, active.ring);
    grow_ring(cs.attachment, band, r, active.ring);
  }
  active.distance_count = collect(cs.distance, band, active.ring, active.distance);
  active.attachment_count = collect(cs.attachment, band, active.ring, active.attachment);
}

}  // namespace imasim::physics
