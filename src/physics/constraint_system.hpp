#pragma once
// All constraints of a world, one coloured flat store per kind, and the set-up helpers that
// derive rest values (length, angle) from the particles' rest positions.
#include <cstdint>
#include <vector>

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
  // Bands (step.cpp): 0 rows of fine objects (every substep), 1 rows of coarse objects (their
  // substeps). Most distance rows are the strands' chains (2 colours), most bending rows fine.
  ConstraintSystem() { dihedral.set_band_colours(20); }

  ColouredStore<DistanceRow> distance;
  ColouredStore<DihedralRow> dihedral;
  ColouredStore<AttachmentRow> attachment;
  // Per object: coarse (ObjectParams::coarse), copied from the model when the object is made
  // (set_object_band); objects not listed are fine.
  std::vector<std::uint8_t> object_band;

  void set_object_band(ObjectId object, bool coarse) {
    if (object_band.size() <= object) object_band.resize(std::size_t(object) + 1, 0);
    object_band[object] = coarse ? 1 : 0;
  }
  // A row's band from its first particle's object (every particle of a row is of one rate).
  std::uint32_t band_of(const Particles& particles, std::uint32_t particle) const {
    const ObjectId o = particles.object[particle];
    return o < object_band.size() ? object_band[o] : 0u;
  }

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
  void reset_lambda(std::uint32_t band) {
    distance.reset_lambda(band);
    dihedral.reset_lambda(band);
    attachment.reset_lambda(band);
  }
};

// Rest length from the rest positions of i and j.
DistanceHandle add_distance(ConstraintSystem& cs, const Particles& particles, std::uint32_t i,
                            std::uint32_t j, MaterialId material, Real compliance_scale = 1);
// Rest angle from the rest positions; wings w0, w1 and shared edge (a, b), as in eq. 3.
DihedralHandle add_dihedral(ConstraintSystem& cs, const Particles& particles, std::uint32_t w0,
                            std::uint32_t w1, std::uint32_t a, std::uint32_t b, MaterialId material,
                            Real compliance_scale = 1);
AttachmentHandle add_attachment(ConstraintSystem& cs, const Particles& particles, std::uint32_t i,
                                const Vec3& target, MaterialId material);
// Moves an attachment's target; false for a stale handle.
bool set_attachment_target(ConstraintSystem& cs, AttachmentHandle h, const Vec3& target);

}  // namespace imasim::physics
