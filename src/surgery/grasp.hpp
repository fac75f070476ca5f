#pragma once
// Grasping with the forceps (SPEC S4): when the jaws close (eq. 16's angle falls below the
// closed threshold), the dynamic tissue particles caught between them attach to the jaws and
// follow them (XPBD attachment constraints whose targets ride in the tool frame); when the jaws
// open again they are released. Through the couplings (2.3.3), lifting the fascia lifts the fat
// under it.
//
// Caught: in the tool frame {l, n, f} at the hinge, 0 <= f.(x - hinge) <= jaw length,
// |l.(x - hinge)| <= width / 2 + margin and |n.(x - hinge)| <= capture_thickness: the tissue
// pinched between the closed jaws. Each caught particle keeps its offset along l and f and is
// pulled onto the jaws' plane (n = 0). The jaws catch the layer they close on: membrane
// particles (fascia, vessel) when any lie between them, else strand particles.
#include <cstdint>
#include <vector>

#include "physics/constraint_system.hpp"
#include "physics/proxy_body.hpp"
#include "surgery/instrument.hpp"
#include "tissue/tissue_world.hpp"

namespace imasim::surgery {

struct GraspParams {
  Real capture_thickness = Real(0.002);  // (unit: m)
  Real margin = Real(0.001);             // beyond the jaws' width (unit: m)
  Real compliance = Real(1e-6);          // of the attachments (unit: m/N)
};

struct Grasper {
  physics::MaterialId material = 0;
  // The proxy body the jaws belong to (physics::State::proxies), or none. With a body the holds
  // are the state's body attachments (physics/body_attachment.hpp: the held tissue pulls the
  // proxy inside the solve; the grasper owns that list); without, attachment rows of the
  // constraint system towards kinematic targets.
  std::uint32_t body = physics::kNoBody;
  bool holding = false;
  bool was_closed = true;
  struct Hold {
    std::uint32_t particle = 0;
    physics::AttachmentHandle attachment;  // without a body
    Vec3 local = Vec3::Zero();             // target in the tool frame (unit: m)
  };
  std::vector<Hold> held;
};

// A grasper whose jaws belong to proxy body `body` (or kNoBody); without a body it registers its
// attachments' material in the world's model (set-up).
Grasper make_grasper(tissue::TissueWorld& world, const GraspParams& params,
                     std::uint32_t body = physics::kNoBody);

// Once per step, after the instrument's pose and jaws are updated: grasps on closing, releases
// on opening, moves the held particles' targets with the jaws (with a body, rewrites the state's
// body attachments). Returns the number held.
std::uint32_t update_grasp(tissue::TissueWorld& world, const GraspParams& params,
                           const InstrumentParams& instrument, const InstrumentState& state,
                           Grasper& grasper);

// The pull of the held tissue on the jaws after a step (the tool proxy feels it):
// each attachment is a spring of the grasp's compliance alpha, so at the end of a converged
// solve it carries f = (target - x) / alpha on its particle and the opposite on the jaws:
//   F_jaws = sum_i (x_i - target_i) / alpha   (unit: N).
// `jaws` is the tool frame the targets ride in (the pose update_grasp last used).
Vec3 grasp_force_on_jaws(const physics::Particles& particles, const GraspParams& params,
                         const Pose& jaws, const Grasper& grasper);

}  // namespace imasim::surgery
