#pragma once
// A default patch of the thoracic wall as the surgeon meets it from inside the chest: the chest
// wall (support, a cylinder patch), the IMA lying 2.75 mm inside it, fat strands from the IMA to
// the wall, the fascia 10 mm inside the wall over both, and fat strands from the fascia to the
// wall, coupled both ways (2.3.3). Frame: z along the IMA (cranio-caudal), y out of the wall
// into the thoracic cavity is -y, gravity (0, -9.81, 0) pulls tissue away from the wall.
#include "geometry/tube.hpp"
#include "tissue/mesh_object.hpp"
#include "tissue/strands.hpp"
#include "tissue/vessel.hpp"

namespace imasim::tissue {

// The paper's 5 ms step, as substeps that converge the default tissues (docs/physics.md).
physics::SolverParams default_solver();

struct ThoracicPatchParams {
  geometry::CylinderPatchSpec wall;
  FasciaParams fascia;
  VesselParams vessel;
  StrandSetParams ima_fat, fascia_fat;
  Real coupling_lambda_max = Real(0.01);  // eq. 8-9 (unit: m)
  Real coupling_radius = Real(0.003);     // strand particles this close are coupled (unit: m)
  physics::SolverParams solver = default_solver();
};

ThoracicPatchParams default_thoracic_patch_params();

struct ThoracicPatch {
  TissueWorld world;
  std::uint32_t wall = 0, fascia = 0, ima = 0;  // world.meshes
  std::uint32_t ima_visual = 0;                 // world.visuals
  std::uint32_t ima_fat = 0, fascia_fat = 0;    // world.strands
};

ThoracicPatch make_thoracic_patch(const ThoracicPatchParams& params);

}  // namespace imasim::tissue
