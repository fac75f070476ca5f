#include "physics/state.hpp"

#include <algorithm>
#include <span>

#include "math/state_hash.hpp"

namespace imasim::physics {

namespace {

template <class T>
void grow(std::vector<T>& v, std::size_t n) {
  if (v.size() < n) v.resize(n);
}

}  // namespace

void prepare_state(const Model& model, State& state) {
  const std::size_t n = state.particles.size();
  StepScratch& s = state.scratch;
  grow(s.saved_position, n);
  grow(s.saved_velocity, n);
  grow(s.projection_terms, model.materials.size());
  grow(s.coarse_terms, model.materials.size());
  grow(s.object_keep, model.objects.size());
  if (s.object_ranges.size() < model.objects.size() || s.ranged_particles != n) {
    // Particles are only ever added (cutting uses reserved ones), so this runs at set-up.
    s.object_ranges.assign(model.objects.size(), ObjectRange{0xffffffffu, 0, 0, 0});
    for (std::size_t i = 0; i < n; ++i) {
      if (state.particles.object[i] >= s.object_ranges.size()) continue;  // validate_state says
      ObjectRange& r = s.object_ranges[state.particles.object[i]];
      r.first = std::min(r.first, static_cast<std::uint32_t>(i));
      r.end = static_cast<std::uint32_t>(i + 1);
    }
    for (ObjectRange& r : s.object_ranges)
      r.first = std::min(r.first, r.end);
    s.ranged_particles = n;
  }
  // Chunks of the per-object passes: each object's range is chunked on its own.
  grow(s.block_first_bad, (n + kParticleBlock - 1) / kParticleBlock + model.objects.size());
  grow(s.validation_stamp, n);
}

std::uint64_t position_hash(const State& state) {
  return hash_span(std::span<const Vec3>(state.particles.position));
}

}  // namespace imasim::physics
