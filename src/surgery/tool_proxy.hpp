#pragma once
// The tool proxy (virtual coupling, SPEC S5 reading; issue 13): the instrument in the physics is
// not where the hand puts it but a proxy coupled to that "device pose" by a spring of stiffness
// k (the force law's k_d of the tissue it presses, eq. 17), and stopped by what it touches. The
// heart and the chest wall stop it outright (the session's god-object stop); deformable tissue
// stops it where the tissue's reaction balances the spring: the proxy sits at
//   x_proxy = x_device + F_tissue / k,
// F_tissue being the force the tissue's contacts put on the tool over the last step (their
// normal impulses / dt). Eq. 17's d is then the depth of the device past the proxy along the
// contact normal, and k d is what both the hand and the tissue feel.
//
// The proxy's offset moves toward its balance by a fraction r a step (a staggered coupling of
// tool and tissue) and never exceeds `max_offset`: the force stays bounded however far the hand
// pushes. With nothing touched F_tissue = 0, so the proxy returns to the device pose.
// The staggered update is a fixed-point iteration: against tissue of local stiffness k_t
// (dF = -k_t do) it converges only while r < 2 / (1 + k_t / k), and fastest at
// r = 1 / (1 + k_t / k). Tissue held taut between anchors, or particles that the tool strikes
// (their impulse per step grows with the tool's own jump), is far stiffer than k, and a fixed r
// then makes the proxy swing from bound to bound. So r = min(relaxation, 1 / (1 + k_t / k)), with
// k_t estimated each step from the last change of force over the last change of offset (a
// secant), decaying by `stiffness_memory` with each new measurement and held at rest.
#include <array>
#include <cstdint>

#include "math/types.hpp"
#include "physics/contact.hpp"
#include "physics/particles.hpp"
#include "surgery/events.hpp"

namespace imasim::surgery {

struct ProxyParams {
  // Coupling stiffness per tissue, indexed by Tissue (unit: N/m); the force law's k_d (eq. 17),
  // copied from it by whoever sets up the haptics (docs/haptics.md).
  std::array<Real, kTissueCount> stiffness{300, 300, 200, 100, 400, 1000};
  Real relaxation = Real(0.5);        // largest fraction of the way to the balance per step (-)
  Real stiffness_memory = Real(0.9);  // the estimated k_t's decay per measurement (-)
  Real max_offset = Real(0.015);      // largest proxy-device distance (unit: m)
};

struct ProxyState {
  Vec3 offset = Vec3::Zero();        // x_proxy - x_device (unit: m)
  Vec3 tissue_force = Vec3::Zero();  // on the tool, mean over the last step (unit: N)
  Tissue pressed = Tissue::none;     // the tissue with the largest share of it
  Real tissue_stiffness = 0;         // k_t estimated from the last steps (unit: N/m)
  Vec3 last_change = Vec3::Zero();   // of the offset at the last update (unit: m)
};

// The force on the tool from the contact rows tagged `tag` over the last step of length dt:
// each row pushed its particle along its normal with normal_impulse, so the tool received the
// opposite. `object_tissue` maps physics objects to tissues; `pressed` gets the tissue with the
// largest impulse (none if no row pushed).
Vec3 tissue_force_on_tool(const physics::ContactSet& contacts,
                          const physics::ObjectId* particle_object, const Tissue* object_tissue,
                          std::size_t object_count, std::uint32_t tag, Real dt, Tissue& pressed);

// One step of the coupling: the offset moves toward F_tissue / k(pressed tissue).
void update_proxy(const ProxyParams& params, const Vec3& tissue_force, Tissue pressed,
                  ProxyState& state);

}  // namespace imasim::surgery
