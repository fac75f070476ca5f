#pragma once
// A mesh object of the world (the fascia) solved by the implicit membrane step
// (physics/implicit_membrane.hpp) instead of its XPBD rows: the mesh at its rest positions, the
// masses its particles have (eq. 5), its fixed particles fixed, its edges the strain-stiffening
// springs of `material` (the toe's modulus, the linear region's past the toe strain), its
// interior edges hinges of the bending stiffness D. The first piece of a fascia at its
// real stiffness (scene/implicit_mesh_scene.hpp steps it in the thorax scene).
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "physics/implicit_membrane.hpp"
#include "physics/membrane_springs.hpp"
#include "tissue/tissue_world.hpp"

namespace imasim::tissue {

struct ImplicitFascia {
  std::uint32_t mesh = 0;                             // in world.meshes
  std::optional<physics::ImplicitMembrane> membrane;  // set by make_implicit_fascia
  std::vector<Vec3> x, v;  // the mesh's vertices, mesh-local, as the step reads and writes them
};

// Throws std::invalid_argument for a mesh out of range, a mesh not flat at rest (its hinges) or
// a material the springs refuse. material.density is not read: the masses are the particles'.
// bending_stiffness: D (unit: N m). h: the step (unit: s).
ImplicitFascia make_implicit_fascia(const TissueWorld& world, std::uint32_t mesh,
                                    const physics::StiffeningMembrane& material,
                                    Real bending_stiffness, Real h, std::uint32_t bodies = 0);

// One step of the fascia alone: reads its particles' positions and velocities (the fixed ones'
// positions are where the caller put them for the step's end), solves, and writes the free ones
// back. Contacts and attachments name mesh-local vertices; body stops, the bodies. exec: the
// threads its elements are evaluated on (the same result on any number).
physics::ImplicitStepReport step_implicit_fascia(
    ImplicitFascia& fascia, TissueWorld& world, const physics::Executor& exec, const Vec3& gravity,
    std::span<const physics::MembraneContact> contacts, std::span<physics::MembraneBody> bodies,
    const physics::ImplicitSolveParams& params,
    std::span<const physics::MembraneAttachment> attachments = {},
    std::span<const physics::MembraneBodyStop> body_stops = {},
    std::span<const physics::MembraneSupport> supports = {});

}  // namespace imasim::tissue
