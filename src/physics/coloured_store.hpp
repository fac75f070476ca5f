#pragma once
// Constraints of one kind, grouped by colour. No two constraints of one colour share a particle,
// so each colour can be projected in parallel without races and with a result that does not
// depend on the thread count. A constraint that finds all kColourCount colours taken by its
// particles goes to the overflow group, which is projected serially after the others.
//
// Colouring is greedy and incremental (lowest colour of its band free for all of the constraint's
// particles),
// so it stays valid as constraints are added and removed after set-up (cutting): each particle
// keeps a bit mask of the colours it appears in. Rows move within their colour on removal
// (swap with the last), and handles (slot + generation) follow them.
#include <array>
#include <bit>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

#include "math/types.hpp"
#include "math/validation_assert.hpp"
#include "physics/handle.hpp"

namespace imasim::physics {

// Rows belong to a band, set when added (physics/constraint_system.hpp, step.cpp): band 0 is
// projected every substep, band 1 every coarse_stride-th substep. Each band colours within
// its own range of the 32 colours and has its own overflow group, so a substep projects exactly
// the colours of its active bands.
inline constexpr std::uint32_t kBandCount = 2;

template <class Row>
class ColouredStore {
 public:
  static constexpr std::uint32_t kColourCount = 32;         // regular colours (bits of a mask)
  static constexpr std::uint32_t kOverflow = kColourCount;  // band 0's overflow group
  static constexpr std::uint32_t kGroupCount = kColourCount + kBandCount;
  // Band b colours with [band_first(b), band_first(b + 1)): a store gives most colours to the
  // band most of its rows are in (set_band_colours, before any row is added).
  std::uint32_t band_first(std::uint32_t band) const { return band_first_[band]; }
  std::uint32_t band_end(std::uint32_t band) const { return band_first_[band + 1]; }
  static constexpr std::uint32_t overflow_group(std::uint32_t band) { return kOverflow + band; }
  void set_band_colours(std::uint32_t first_of_band_1) {
    band_first_ = {0, first_of_band_1, kColourCount};
  }

  // A row's multiplier: one per scalar constraint row (Real), or one per axis for a vector row
  // (Row::Lambda, the attachment's three linear rows).
  using Lambda = typename Row::Lambda;

  struct Group {
    std::vector<Row> rows;
    std::vector<Lambda> lambda;  // accumulated multiplier per row, reset every substep
  };

  Handle<Row> add(Row row, std::uint32_t band = 0) {
    std::uint32_t mask = 0;
    for (std::uint32_t p : row.particles()) {
      ensure_particle(p);
      mask |= particle_colours_[p];
    }
    const std::uint32_t first = band_first(band), end = band_end(band);
    const std::uint32_t allowed =
        (end == 32 ? ~0u : (1u << end) - 1u) & ~(first == 0 ? 0u : (1u << first) - 1u);
    const std::uint32_t free = ~mask & allowed;
    const std::uint32_t group =
        free != 0 ? static_cast<std::uint32_t>(std::countr_zero(free)) : overflow_group(band);
    if (group < kColourCount) {
      for (std::uint32_t p : row.particles()) {
        IMASIM_ASSERT((particle_colours_[p] & (1u << group)) == 0);  // a colour's rows share none
        particle_colours_[p] |= 1u << group;
      }
    }
    const std::uint32_t slot = allocate_slot();
    row.slot = slot;
    Group& g = groups_[group];
    slots_[slot].group = group;
    slots_[slot].position = static_cast<std::uint32_t>(g.rows.size());
    g.rows.push_back(row);
    g.lambda.push_back(zero_lambda());
    ++size_;
    return {slot, slots_[slot].generation};
  }

  // Removes the constraint; returns false (and does nothing) for a stale or null handle.
  bool remove(Handle<Row> h) {
    if (!resolves(h)) return false;
    Slot& s = slots_[h.index];
    IMASIM_ASSERT(s.group < kGroupCount && s.position < groups_[s.group].rows.size());
    Group& g = groups_[s.group];
    if (s.group < kColourCount) {
      for (std::uint32_t p : g.rows[s.position].particles())
        particle_colours_[p] &= ~(1u << s.group);
    }
    const std::uint32_t last = static_cast<std::uint32_t>(g.rows.size() - 1);
    if (s.position != last) {
      g.rows[s.position] = g.rows[last];
      g.lambda[s.position] = g.lambda[last];
      slots_[g.rows[s.position].slot].position = s.position;
    }
    g.rows.pop_back();
    g.lambda.pop_back();
    s.live = false;
    ++s.generation;
    free_slots_.push_back(h.index);
    --size_;
    return true;
  }

  // The handle of the live constraint whose row carries `slot` (rows keep their slot as a
  // back-reference), for indexes built from the rows.
  Handle<Row> handle_of(const Row& row) const { return {row.slot, slots_[row.slot].generation}; }

  bool resolves(Handle<Row> h) const {
    return h.index < slots_.size() && slots_[h.index].live &&
           slots_[h.index].generation == h.generation;
  }
  Row* find(Handle<Row> h) {
    return resolves(h) ? &groups_[slots_[h.index].group].rows[slots_[h.index].position] : nullptr;
  }
  const Row* find(Handle<Row> h) const {
    return resolves(h) ? &groups_[slots_[h.index].group].rows[slots_[h.index].position] : nullptr;
  }

  std::span<Group> groups() { return groups_; }
  std::span<const Group> groups() const { return groups_; }
  std::size_t size() const { return size_; }
  std::size_t overflow_size() const {
    std::size_t n = 0;
    for (std::uint32_t b = 0; b < kBandCount; ++b)
      n += groups_[overflow_group(b)].rows.size();
    return n;
  }
  // Groups that hold at least one constraint, the overflow group included.
  std::uint32_t non_empty_groups() const {
    std::uint32_t n = 0;
    for (const Group& g : groups_)
      n += g.rows.empty() ? 0u : 1u;
    return n;
  }
  // Bit c set: particle appears in a constraint of colour c (for validation).
  std::uint32_t particle_colour_mask(std::uint32_t p) const {
    return p < particle_colours_.size() ? particle_colours_[p] : 0u;
  }

  void reset_lambda() {
    for (Group& g : groups_)
      std::fill(g.lambda.begin(), g.lambda.end(), zero_lambda());
  }
  void reset_lambda(std::uint32_t band) {
    for (std::uint32_t g = band_first(band); g < band_end(band); ++g)
      std::fill(groups_[g].lambda.begin(), groups_[g].lambda.end(), zero_lambda());
    Group& o = groups_[overflow_group(band)];
    std::fill(o.lambda.begin(), o.lambda.end(), zero_lambda());
  }

 private:
  static Lambda zero_lambda() {
    if constexpr (std::is_same_v<Lambda, Real>) {
      return Real(0);
    } else {
      return Lambda::Zero();
    }
  }

  struct Slot {
    std::uint32_t group = 0, position = 0, generation = 0;
    bool live = false;
  };

  void ensure_particle(std::uint32_t p) {
    if (p >= particle_colours_.size()) particle_colours_.resize(std::size_t(p) + 1, 0u);
  }
  std::uint32_t allocate_slot() {
    std::uint32_t slot;
    if (!free_slots_.empty()) {
      slot = free_slots_.back();
      free_slots_.pop_back();
    } else {
      slot = static_cast<std::uint32_t>(slots_.size());
      slots_.emplace_back();
    }
    slots_[slot].live = true;
    return slot;
  }

  std::array<Group, kGroupCount> groups_;
  std::array<std::uint32_t, kBandCount + 1> band_first_ = {0, 24, kColourCount};
  std::vector<std::uint32_t> particle_colours_;
  std::vector<Slot> slots_;
  std::vector<std::uint32_t> free_slots_;
  std::size_t size_ = 0;
};

}  // namespace imasim::physics
