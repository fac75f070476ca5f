#pragma once
// The tool proxy (virtual coupling, SPEC S5 reading): the instrument in the
// physics is not where the hand puts it but a proxy coupled to that "device pose" by a stiff
// spring and damper, one coupling for every tissue, and stopped by what it touches. The heart and
// the chest wall stop it inside the solve as well, through rows between the body and their
// surfaces (physics/body_stop.hpp; the session's god-object stop before the step guards only
// against a motion through them). Deformable tissue stops it inside the solve: the proxy is a
// physics::ProxyBody whose offset o from the device is an unknown of the step, and the instrument's
// contact rows are two-body constraints with it, so the tissue's reaction pushes the proxy back in
// the same substeps in which the tool pushes the tissue (physics/proxy_body.hpp). At rest k o is
// the force the tissue pushes the tool with. The coupling is apart from eq. 17's k_d: the device
// and the tissue are springs in series, so a coupling of the tissue's own k_d would let the hand
// feel half the tissue's push at most, and one that changed with the tissue touched would switch
// between steps as rows come and go (the held hook's force chattered step to step between the
// fascia's 300 and the fat's 100 N/m). Stiff, it leaves the hand what the tissue pushes: the
// local model (console/local_model_of.hpp) renders it at each tissue's k_d. With nothing touched
// the proxy returns to the device pose (time constant c / k, 5 ms).
//
// Held tissue pulls the forceps through the grasp's attachments, which name the body as well
// (physics/body_attachment.hpp): the pull moves the proxy within the same substeps, and at rest
// k o balances the push and the pull together.
#include <array>
#include <cstdint>
#include <span>

#include "math/types.hpp"
#include "physics/contact.hpp"
#include "physics/particles.hpp"
#include "physics/proxy_body.hpp"
#include "surgery/events.hpp"

namespace imasim::surgery {

struct ProxyParams {
  // Eq. 17's k_d per tissue, indexed by Tissue (unit: N/m), copied from the force law by whoever
  // sets up the haptics (docs/haptics.md): the stiffness each tissue is rendered at
  // (console/local_model_of.hpp).
  std::array<Real, kTissueCount> stiffness{Real(4.3), Real(4.3), 34, Real(4.3), 400, 1000};
  // The coupling, one for every tissue: stiff beside the tissues' k_d, so the hand feels what the
  // tissue pushes (unit: N/m), and damped to a 5 ms time constant (unit: N s/m).
  Real coupling_stiffness = 1000;
  Real coupling_damping = 5;
  // Coulomb's mu between the tool and each tissue, eq. 18's mu (-): one coefficient per pair, so
  // the drag the tool puts on the tissue and the one the hand feels are the same friction. It is
  // the contact rows' static and kinetic friction alike.
  std::array<Real, kTissueCount> friction{Real(0.2), Real(0.2), Real(0.15),
                                          Real(0.1), Real(0.1), Real(0.3)};
  Real max_offset = Real(0.015);  // largest proxy-device distance (unit: m)
};

struct ProxyState {
  Vec3 offset = Vec3::Zero();        // x_proxy - x_device after the last step (unit: m)
  Vec3 tissue_force = Vec3::Zero();  // on the tool, mean over the last step (unit: N)
  // Its part along the contacts' normals, plus the pull: eq. 17's normal channel. The rest of
  // tissue_force is the contacts' friction, which the haptic loop renders as eq. 18 instead.
  Vec3 normal_force = Vec3::Zero();  // (unit: N)
  Tissue pressed = Tissue::none;     // the tissue with the largest share of it
  Tissue stopped_by = Tissue::none;  // the heart or the wall, if their rows pushed the proxy
  Vec3 pull = Vec3::Zero();          // the held tissue's, on the jaws after the last step (unit: N)
  Tissue held = Tissue::none;        // the tissue pulling, if any
  Real coupling = 0;                 // the last step's k, which took the offset (unit: N/m)
};

// The force on the tool from the contact rows tagged `tag` over the last step of length dt:
// each row pushed its particle along its normal with normal_impulse, so the tool received the
// opposite. `object_tissue` maps physics objects to tissues; `pressed` gets the tissue with the
// largest impulse (none if no row pushed).
Vec3 tissue_force_on_tool(const physics::ContactSet& contacts,
                          const physics::ObjectId* particle_object, const Tissue* object_tissue,
                          std::size_t object_count, std::uint32_t tag, Real dt, Tissue& pressed);

// Before a step, with the instrument's contact rows gathered (`rows`): they name the body
// (`body_index` in the state's proxies), and the body takes the coupling, the bound and the
// offset the proxy ended the last step with (its spring relaxed at the device). Each row takes
// its own tissue's friction (a particle of no tissue keeps the row's).
void prepare_proxy_body(const ProxyParams& params, const ProxyState& state,
                        std::span<physics::ContactRow> rows, std::uint32_t body_index,
                        const physics::ObjectId* particle_object, const Tissue* object_tissue,
                        std::size_t object_count, physics::ProxyBody& body);

// After a step of length dt: the offset the solve left, the force on the tool (everything the
// body received over the step: the contacts' push and friction, the held tissue's pull, the heart's
// and the wall's push; at rest k o), its normal channel (`normal_push`, the contacts' normal
// impulses over dt from tissue_force_on_tool, plus the held tissue's `pull`), the tissue pressed
// (`pressed`, or `pull_tissue` when the pull is the larger part of the channel), the tissue
// held (`pull_tissue` while it pulls), the surface that stopped it (`stopped_by`) and the
// coupling's k. A non-finite pull or push is none.
void finish_proxy_step(const physics::ProxyBody& body, Real dt, const Vec3& normal_push,
                       Tissue pressed, const Vec3& pull, Tissue pull_tissue, Tissue stopped_by,
                       ProxyState& state);

}  // namespace imasim::surgery
