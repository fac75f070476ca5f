#pragma once
// All constraints of a world, one coloured flat store per kind, and the set-up helpers that
// derive rest values (length, angle) from the particles' rest positions.
#include <cstdint>

#include "physics/attachment_constraint.hpp"
#include "physics/coloured_store.hpp"
#include "physics/dihedral_constraint.hpp"
#include "physics/distance_constraint.hpp"
#include "physics/particles.hpp"

namespace imasim::physics {

using DistanceHandle = Handle<DistanceRow>;
using DihedralHandle = Handle<DihedralRow>;
using AttachmentHandle = Handle<AttachmentRow>;

struct ConstraintSystem {
  ColouredStore<DistanceRow> distance;
  ColouredStore<DihedralRow> dihedral;
  ColouredStore<AttachmentRow> attachment;

  // Colour groups with work in them, over all kinds: the parallel phases of one sweep.
  std::uint32_t non_empty_groups() const {
    return distance.non_empty_groups() + dihedral.non_empty_groups() +
           attachment.non_empty_groups();
  }
  std::size_t overflow_size() const {
    return distance.overflow_size() + dihedral.overflow_size() + attachment.overflow_size();
  }
  void reset_lambda() {
    distance.reset_lambda();
    dihedral.reset_lambda();
    attachment.reset_lambda();
  }
};

// Rest length from the rest positions of i and j.
DistanceHandle add_distance(ConstraintSystem& cs, const Particles& particles, std::uint32_t i,
                            std::uint32_t j, MaterialId material);
// Rest angle from the rest positions; wings w0, w1 and shared edge (a, b), as in eq. 3.
DihedralHandle add_dihedral(ConstraintSystem& cs, const Particles& particles, std::uint32_t w0,
                            std::uint32_t w1, std::uint32_t a, std::uint32_t b,
                            MaterialId material);
AttachmentHandle add_attachment(ConstraintSystem& cs, const Particles& particles, std::uint32_t i,
                                const Vec3& target, MaterialId material);
// Moves an attachment's target; false for a stale handle.
bool set_attachment_target(ConstraintSystem& cs, AttachmentHandle h, const Vec3& target);

}  // namespace imasim::physics
