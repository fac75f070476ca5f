#pragma once
// Connective-tissue strands in the world (2.3.4): generated between two mesh objects, each strand
// a chain of n distance constraints (eq. 2) over n + 1 particles whose two ends are kinematic and
// ride on their surfaces through barycentric bindings.
#include <string>

#include "tissue/strand_generator.hpp"
#include "tissue/tissue_world.hpp"

namespace imasim::tissue {

struct StrandSetParams {
  std::string name = "fat";
  StrandParams generation;
  Real diameter = Real(1.5e-3);  // drawn particle diameter (unit: m)
  Real total_mass = Real(0.02);  // spread over the interior particles (unit: kg)
  bool gravity = true;
  Real linear_damping = Real(0.03);  // k_l of eq. 4: share of velocity removed per 5 ms
  // Soft (fat): stepped at the solver's coarse rate, which converges it (docs/physics.md).
  bool coarse = true;
  // Young's modulus of the connective tissue (unit: Pa): breast fat 3.25 +- 0.91 kPa (Samani et
  // al. 2007, docs/tissue.md). Each strand stands for the tissue over its share of its source
  // face, A_s = face area / sigma, so a segment of length L has k = E A_s / L: the layer's
  // stiffness depends on neither sigma, n nor the mesh.
  Real youngs_modulus = Real(3250);
  // Stretch at which a strand tears: its ends further apart than this many times their rest
  // distance. Not a measured rupture strain: the scripted harvests stretch strands up to 2.05
  // times by retraction (docs/tissue.md), and a strand whose end rides on a piece of fascia that
  // fell away would otherwise be stretched tens of times, its particles jittering metres a second
  // until the step's speed guard stops the run.
  Real tear_stretch = Real(3);
  // The fat holds what it binds and pushes back when compressed towards mesh_b (a base whose
  // particles are all fixed): each strand is also a column of its share of the layer, E A_s / L
  // (fat_support.hpp). Off (the default until the scene is refitted to it, docs/physics.md): the
  // strands are chains whose ends ride on their surfaces, which buckle when pushed along their
  // length.
  bool resists_compression = false;
  Real xsph_coefficient = Real(0.3);  // share of the neighbours' mean velocity taken per step
  Real xsph_radius = Real(4e-3);      // neighbourhood at rest (unit: m)
};

// Returns the index of the new set in world.strands. Set-up only.
std::uint32_t add_strands(TissueWorld& world, std::uint32_t mesh_a, std::uint32_t mesh_b,
                          const StrandSetParams& params);

// Interior (non-end) particles of a strand set, in order.
std::vector<std::uint32_t> interior_particles(const StrandSet& set);

// Puts every strand end on its surface (positions only; the ends are kinematic).
void place_strand_ends(TissueWorld& world);

}  // namespace imasim::tissue
