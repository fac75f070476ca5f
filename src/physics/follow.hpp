#pragma once
// A particle that follows another's offset inside the solve (the couplings of eq. 8 and eq. 9
// with beta = 1, SPEC S2): the destination is held at
//   x_dst = r_dst + O / |O| min(|O|, max_offset),  O = x_src - r_src,
// with r the two particles' reference positions for the step. The source is read, never moved
// (the coupling is one way); the destination is put there in every substep of its band, after
// the band's constraints, so the solver's velocity (p - x) / h is the destination's real motion
// and nothing fights the coupling after the step.
#include <cstdint>
#include <vector>

#include "math/types.hpp"

namespace imasim::physics {

struct FollowRow {
  std::uint32_t source = 0, destination = 0;
  Vec3 source_reference = Vec3::Zero(), destination_reference = Vec3::Zero();  // (unit: m)
  Real max_offset = 0;  // lambda_max of eq. 8-9 (unit: m)
};

// source: where the source is (p[f.source], or where it was as the step's group of substeps
// began when it is in the other rate band: physics/step.cpp).
inline void project_follow(const FollowRow& f, const Vec3& source, Vec3* p) {
  const Vec3 offset = source - f.source_reference;
  const Real len = offset.norm();
  p[f.destination] = len > f.max_offset
                         ? Vec3(f.destination_reference + (f.max_offset / len) * offset)
                         : Vec3(f.destination_reference + offset);
}

}  // namespace imasim::physics
