#pragma once
// Connective-tissue strand generator (2.3.4, Fig. 7): strands from the faces of surface A to
// surface B. sigma strands per face (its fractional part is the probability of one more), each
// leaving a random point of its face in a random direction within theta of the face normal and
// ending where that ray meets B within d_max (given, or eq. 6: the distance between the two
// surfaces' centres). Only faces that face each other are used: a face of A is eligible when
// the ray along its normal from its centre meets B, and a strand is kept only where B's face
// turns towards it. B's triangles sit in a uniform grid, so no ray tests all of B.
// Deterministic for a seed (SplitMix64).
#include <array>
#include <cstdint>
#include <vector>

#include "geometry/triangle_mesh.hpp"

namespace imasim::tissue {

struct StrandParams {
  Real strands_per_face = 1;    // sigma
  std::uint32_t segments = 4;   // n
  Real max_length = 0;          // d_max (unit: m); 0 = eq. 6
  Real max_angle = Real(0.35);  // theta (unit: rad), 20 deg
  std::uint64_t seed = 1;
  std::uint32_t attempts = 16;  // directions tried for one strand before it is dropped
};

struct GeneratedStrand {
  std::uint32_t face_a = 0, face_b = 0;
  std::array<Real, 3> bary_a = {1, 0, 0}, bary_b = {1, 0, 0};
  Vec3 start = Vec3::Zero(), end = Vec3::Zero();  // on A and on B (unit: m)
};

struct StrandGeneration {
  std::vector<GeneratedStrand> strands;
  std::vector<std::uint32_t> eligible_faces;  // faces of A that face B
  Real max_length = 0;                        // the d_max used (unit: m)
  std::uint32_t dropped = 0;                  // strands with no admissible direction found
};

// Throws std::invalid_argument for sigma < 0, n < 1, theta outside [0, pi/2) or empty meshes.
StrandGeneration generate_strands(const geometry::TriangleMesh& a, const geometry::TriangleMesh& b,
                                  const StrandParams& params);

// eq. 6: distance between the centres (vertex means) of two surfaces (unit: m).
Real centre_distance(const geometry::TriangleMesh& a, const geometry::TriangleMesh& b);

}  // namespace imasim::tissue
