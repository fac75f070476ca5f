#pragma once
// Electrocautery (SPEC S4, S5): a hook or spatula electrode energised by the foot pedal in cut
// or coagulation mode at 30-50 W. While the pedal is pressed and the electrode touches tissue
// (a dynamic tissue particle within `contact_radius` of it), a share of the electrical energy,
// E = eta P dt (unit: J), heats the tissue around the electrode. The electrode is a line source
// of length L with a Gaussian cross-section, sigma = spread_radius / 2: the heat per volume at
// distance r from it is
//   q(r) = E exp(-(r / sigma)^2) / (pi sigma^2 (L + sqrt(pi) sigma))        (unit: J/m^3),
// whose integral over space is E (the two end caps together make one 3D Gaussian), cut off at
// `spread_radius`. The tissue there is a continuum that the particles sample: a particle at r
// rises by q(r) / (rho c); between deposits the tissue cools by conduction (cool_tissue). The
// rise so depends on the distance alone, not on how many particles happen to lie near the
// electrode (the fat's strands sample their tissue sparsely) nor on their masses, so it does not
// change with the mesh's resolution or with a cut. A vertex a cut makes takes its parents' rise
// interpolated like its position (inherit_cautery_state). Past the coagulation rise the tissue is
// coagulated: its stretch constraints take a stiffer material (compliance times
// `coagulated_compliance_factor`) and it is drawn in the coagulated colour. On the IMA, a rise past
// `injury_rise` is a thermal injury. Cut mode's cutting itself (fascia and strands) is the
// session's: it calls the cutters while this reports contact.
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "surgery/pedal.hpp"
#include "tissue/tissue_world.hpp"
#include "tissue/topology_change.hpp"

namespace imasim::surgery {

struct CauteryParams {
  Real power = 40;                      // P (unit: W), within [30, 50]
  Real electrode_length = Real(0.008);  // active part from the hinge along f (unit: m)
  Real contact_radius = Real(0.001);    // touching within this of the electrode (unit: m)
  Real spread_radius = Real(0.003);     // heat reaches this far (unit: m)
  // Share of P dt that heats the tissue: cut mode vaporises a thin layer at the edge (most of
  // the energy leaves as steam), coagulation mode heats the surroundings.
  Real cut_heat_fraction = Real(0.2), coag_heat_fraction = Real(0.6);
  Real specific_heat = 3500;  // c of soft tissue (unit: J/(kg K))
  Real density = 1050;        // rho of soft tissue (unit: kg/m^3)
  // alpha = k / (rho c) of soft tissue (0.5 W/(m K)); it sets how fast a hot spot of the
  // line source's width cools (cooling_time) (unit: m^2/s). 0: no cooling.
  Real thermal_diffusivity = Real(1.4e-7);
  Real coagulation_rise = 23;  // 37 -> 60 degC coagulates (unit: K)
  Real injury_rise = 8;        // 37 -> 45 degC injures the IMA's wall (unit: K)
  Real coagulated_compliance_factor = Real(0.1);
};

// Throws std::invalid_argument naming the field (power outside [30, 50] W, non-positive sizes).
void validate(const CauteryParams& params);

struct CauteryState {
  std::vector<Real> rise;  // temperature rise per particle (unit: K)
  Real dose = 0;           // heat delivered to the tissue, sum of E, for reports (unit: J)
  std::vector<std::uint8_t> coagulated, injured;
  std::size_t coagulated_count = 0;
  std::vector<std::uint8_t> heatable;  // per object: tissue the electrode can heat
  std::uint32_t ima_object = 0xffffffffu;
  // Per material: its coagulated counterpart (added to the model at set-up).
  std::vector<physics::MaterialId> coagulated_material;
  std::vector<std::uint32_t> reached;  // scratch: particles within the spread radius
  std::vector<Real> weight;            // scratch
};

// Set-up: sizes the state for the world's particles and adds the coagulated materials. `heatable`
// are the objects (physics::ObjectId) of tissue; `ima_object` the vessel's.
CauteryState make_cautery_state(tissue::TissueWorld& world, const CauteryParams& params,
                                const std::vector<physics::ObjectId>& heatable,
                                physics::ObjectId ima_object);

struct CauteryStep {
  bool active = false;           // pedal pressed
  std::uint32_t touching = 0;    // particles within the contact radius
  Real energy = 0;               // heat deposited this step (unit: J)
  std::uint32_t coagulated = 0;  // particles newly coagulated
  std::uint32_t injured = 0;     // IMA particles newly injured
  Real max_ima_rise = 0;         // largest temperature rise on the IMA (unit: K)
};

// Conduction spreads a Gaussian hot spot of width sigma: its peak falls as
// sigma^2 / (sigma^2 + 4 alpha t), at first at the rate 4 alpha / sigma^2. A lumped model keeps
// that rate: each particle's rise relaxes as d(rise)/dt = -rise / tau, tau = sigma^2 / (4 alpha)
// (4.0 s at the defaults). It drops the heat conducted outwards instead of adding it to the
// neighbours, which a point 2 mm from the electrode would see as up to a fifth more of its peak
// rise, a second later; without it, passes 20 s apart would add up as if the tissue held every
// joule for the whole session. Returns tau (unit: s), infinite without diffusivity.
Real cooling_time(const CauteryParams& params);

// One step of cooling: every rise times exp(-dt / tau). The flags (coagulated, injured) stay.
void cool_tissue(const CauteryParams& params, Real dt, CauteryState& state);

// One step with the electrode from a to b (world, unit: m).
CauteryStep apply_cautery(tissue::TissueWorld& world, const CauteryParams& params, PedalMode pedal,
                          const Vec3& a, const Vec3& b, Real dt, CauteryState& state);

// Temperature rise of particle i (unit: K); 0 for a fixed particle (never heated: its mass is
// not modelled).
inline Real temperature_rise(const CauteryState& state, std::uint32_t i) {
  return state.rise[i];
}

// After a topology change of world.meshes[mesh] that made `vertices` (new vertex k is mesh-local
// first_new_vertex + k, its parents made before it): each new vertex takes the rise
// (1 - t) dT_a + t dT_b of its parents (a copy its parent's), the same weight as its position;
// it is coagulated (injured, on the IMA) when both parents are (a copy when its parent is) or
// when that rise reaches the threshold, so the flags keep meaning "the rise reached it".
// O(new vertices); call it before stiffen_coagulated.
void inherit_cautery_state(const tissue::TissueWorld& world, const CauteryParams& params,
                           std::uint32_t mesh, std::uint32_t first_new_vertex,
                           std::span<const tissue::NewVertex> vertices, CauteryState& state);

// Gives every stretch constraint on a coagulated particle the coagulated material again (after a
// topology change rebuilt constraints with the tissue's own material).
void stiffen_coagulated(tissue::TissueWorld& world, CauteryState& state);

// Display colour: `base` blended towards coagulated tissue's pale brown as the rise approaches
// the coagulation rise.
Vec3 coagulation_colour(const Vec3& base, Real rise, const CauteryParams& params);

}  // namespace imasim::surgery
