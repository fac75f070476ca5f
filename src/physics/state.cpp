#include "physics/state.hpp"

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
  grow(s.bending_terms, model.materials.size());
  grow(s.group_start, n);
  // Carried between steps and read before written: zeroed (Eigen's vectors are not).
  if (state.velocity_offset.size() < n) state.velocity_offset.resize(n, Vec3::Zero());
  grow(s.object_keep, model.objects.size());
  grow(s.object_ranges, model.objects.size());  // filled by each step (step.cpp)
  // Chunks of the per-object passes: each object's range is chunked on its own.
  grow(s.block_first_bad, (n + kParticleBlock - 1) / kParticleBlock + model.objects.size());
  grow(s.validation_stamp, n);
  prepare_active_rows(state, s.coarse_active);
}

std::uint64_t position_hash(const State& state) {
  return hash_span(std::span<const Vec3>(state.particles.position));
}

}  // namespace imasim::physics
