// A tool pressed into the fascia feels a force set by the membrane, not by the solver settings
// (SPEC S1): the default solve is within 5 % of a 4x finer one. The sensitive case: a membrane
// held at its edges pushes back as the cube of the indentation, so a solver that leaves it soft
// shows up in full in the force, where it hides as a cube root in a sag. The implicit membrane
// step presses it as converged XPBD does. Release only, label `physics`.
#include <gtest/gtest.h>

#include <algorithm>

#include "physics/executor.hpp"
#include "physics/implicit_membrane.hpp"
#include "physics/membrane_springs.hpp"
#include "surgery/tool_contact.hpp"
#include "surgery/tool_proxy.hpp"
#include "tissue/mesh_object.hpp"
#include "tissue/thoracic_patch.hpp"
#include "tissue/tissue_step.hpp"

namespace imasim {
namespace {

using surgery::Tissue;

constexpr std::uint32_t kTag = 3;
constexpr Real kBallRadius = Real(0.005);  // a ball-ended probe (unit: m)

struct Press {
  std::uint32_t substeps = 32, stretch_sweeps = 2;
  bool proxy = false;     // coupled through the tool proxy (eq. 17), else a rigid ball
  bool friction = false;  // the tool's default friction (eq. 18's mu), else frictionless
  Real depth = 0;         // the device's ball past the membrane's rest surface (unit: m)
};

// The fascia without gravity, its perimeter fixed, pressed at its centre by a frictionless ball
// lowered from 15 mm above its final place at 20 mm/s, then held for a quarter second: the tissue's
// force on the tool at the end (unit: N).
// The fascia of the press, its perimeter fixed, without gravity; where the ball ends (device)
// and where it starts, 15 mm above.
struct Rig {
  tissue::TissueWorld world;
  std::uint32_t mesh = 0;
  Vec3 device = Vec3::Zero(), start = Vec3::Zero();
};

void make_rig(const Press& press, Rig& rig) {
  rig.world.model.solver = tissue::default_solver();
  rig.world.model.solver.substeps = press.substeps;
  rig.world.model.solver.stretch_sweeps = press.stretch_sweeps;
  tissue::FasciaParams f = tissue::default_fascia_params();
  f.object.gravity = false;
  rig.mesh = tissue::add_fascia(rig.world, f);
  tissue::finish_setup(rig.world);
  const auto x = tissue::mesh_positions(rig.world, rig.world.meshes[rig.mesh]);
  Vec3 lo = x[0], hi = x[0];
  for (const Vec3& p : x)
    lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  rig.device = Real(0.5) * (lo + hi) + Vec3(0, kBallRadius - press.depth, 0);
  rig.start = rig.device + Vec3(0, Real(0.015), 0);
}

Real press_force(const Press& press) {
  Rig rig;
  make_rig(press, rig);
  tissue::TissueWorld& world = rig.world;
  const std::uint32_t mesh = rig.mesh;
  const Vec3 device = rig.device, start = rig.start;
  world.state.proxies.assign(1, physics::ProxyBody{});
  std::vector<Tissue> object_tissue(world.model.objects.size(), Tissue::none);
  object_tissue[world.meshes[mesh].object] = Tissue::fascia;

  surgery::ProxyParams params;
  if (!press.proxy) params.coupling_stiffness = 0;  // inactive: rigid
  surgery::ContactParams contact;
  if (!press.friction) {  // a unique rest
    contact.static_friction = contact.kinetic_friction = 0;
    params.friction.fill(0);
  }
  surgery::ProxyState proxy;
  physics::Executor exec(2);
  const Real dt = world.model.solver.dt;
  const int travel_steps = int(Real(0.015) / (Real(0.02) * dt));
  Vec3 previous = start;
  Vec3 force = Vec3::Zero();
  for (int k = 0; k < travel_steps + 50; ++k) {
    const Real s = std::min(Real(1), Real(k) / Real(travel_steps));
    const Vec3 at = start + s * (device - start) + proxy.offset;
    surgery::ToolGeometry tool;
    tool.capsules.push_back({at, at, kBallRadius});
    tool.velocity = (at - previous) / dt;
    Pose before, now;
    before.translation = previous;
    now.translation = at;
    world.state.contacts.clear();
    surgery::gather_tool_contacts(world.state.particles, tool, before, now, contact, dt, kTag,
                                  world.state.contacts);
    surgery::prepare_proxy_body(params, proxy, world.state.contacts.rows, 0,
                                world.state.particles.object.data(), object_tissue.data(),
                                object_tissue.size(), world.state.proxies[0]);
    EXPECT_TRUE(tissue::step_tissue(world, exec).ok());
    Tissue pressed = Tissue::none;
    const Vec3 normal = surgery::tissue_force_on_tool(
        world.state.contacts, world.state.particles.object.data(), object_tissue.data(),
        object_tissue.size(), kTag, dt, pressed);
    surgery::finish_proxy_step(world.state.proxies[0], dt, normal, pressed, Vec3::Zero(),
                               Tissue::none, Tissue::none, proxy);
    force = press.proxy ? proxy.tissue_force : normal;
    previous = at + world.state.proxies[0].carried();
  }
  return force.norm();
}

// One press at the default, at a finer setting and with one sweep (unit: N).
struct PressFigures {
  Real by_default = 0, reference = 0, one_sweep = 0;
};

PressFigures press_three(const Press& p, std::uint32_t fine_substeps, std::uint32_t fine_sweeps) {
  Press fine = p;
  fine.substeps = fine_substeps, fine.stretch_sweeps = fine_sweeps;
  Press one = p;
  one.stretch_sweeps = 1;
  return {press_force(p), press_force(fine), press_force(one)};
}

// The implicit step, one a 5 ms step, on the same mesh, masses and fixed perimeter, its edges
// at the fascia's toe modulus E_t and, past toe_strain, E_l, its hinges the fascia's bending:
// the ball's force at the end (unit: N). press.proxy: the ball is a body solved with the
// membrane, held to the device by the proxy's coupling (eq. 17's spring and damper).
Real implicit_press(Real linear_modulus, Real toe_strain,
                    const Press& press = {.depth = Real(0.0115)}) {
  Rig f;
  make_rig(press, f);
  const tissue::TissueWorld& w = f.world;
  const tissue::MeshObject& m = w.meshes[f.mesh];
  geometry::TriangleMesh mesh;
  const auto x0 = tissue::mesh_positions(w, m);
  mesh.vertices.assign(x0.begin(), x0.end());
  mesh.triangles = m.triangles;
  std::vector<Real> mass(mesh.vertices.size(), 0);
  std::vector<std::uint8_t> fixed(mesh.vertices.size(), 0);
  for (std::uint32_t v = 0; v < mesh.vertices.size(); ++v) {
    const Real inverse = w.state.particles.inverse_mass[m.first_particle + v];
    fixed[v] = inverse == 0;
    mass[v] = inverse == 0 ? 0 : 1 / inverse;
  }
  const physics::MembraneMaterial fascia = tissue::default_fascia_membrane();
  physics::StiffeningMembrane material;
  material.toe_modulus = fascia.youngs_modulus;
  material.linear_modulus = linear_modulus;
  material.toe_strain = toe_strain;
  material.thickness = fascia.thickness;
  physics::ImplicitMembrane membrane(
      mass, fixed, physics::membrane_springs(mesh, material), w.model.solver.dt,
      physics::membrane_hinges(mesh, fascia.effective_bending_stiffness()), press.proxy ? 1 : 0);
  const surgery::ProxyParams coupling;
  std::vector<physics::MembraneBody> bodies;
  if (press.proxy) {
    bodies.push_back({f.start, coupling.coupling_stiffness, coupling.coupling_damping, f.start});
  }
  std::vector<Vec3> x = mesh.vertices, v(x.size(), Vec3::Zero());
  std::vector<physics::MembraneContact> contacts;
  const physics::ImplicitSolveParams solve;
  const Real dt = w.model.solver.dt;
  const int travel = int(Real(0.015) / (Real(0.02) * dt));
  Vec3 force = Vec3::Zero();
  for (int k = 0; k < travel + 50; ++k) {
    const Vec3 device = f.start + std::min(Real(1), Real(k) / Real(travel)) * (f.device - f.start);
    // The ball: where the device is, or the proxy body where it starts the step.
    const Vec3 at = press.proxy ? bodies[0].position : device;
    if (press.proxy) bodies[0].anchor = device;
    // Each vertex near the ball kept outside it and the tool contacts' margin, on the tangent
    // plane facing where it starts: the XPBD press's tool.
    const Real reach = kBallRadius + surgery::ContactParams{}.margin;
    contacts.clear();
    for (std::uint32_t u = 0; u < x.size(); ++u) {
      const Vec3 out = x[u] - at;
      if (fixed[u] || out.norm() > kBallRadius + Real(0.003) || !(out.norm() > 0)) continue;
      const Vec3 n = out.normalized();
      contacts.push_back({u, at + reach * n, n, press.proxy ? 0 : physics::kNoMembraneBody});
    }
    const physics::ImplicitStepReport r =
        membrane.step(x, v, {Vec3::Zero(), {}, contacts, bodies}, solve);
    EXPECT_TRUE(r.ok);
    EXPECT_LT(r.residual, solve.tolerance) << "step " << k;
    // What each contact pushed at the step's end: a held vertex's plane reaction, or the penalty.
    force = Vec3::Zero();
    for (std::size_t c = 0; c < contacts.size(); ++c)
      force -= membrane.contact_forces()[c] * contacts[c].normal;
    if (press.proxy) {  // at rest the coupling carries what the contacts push
      const Vec3 spring = coupling.coupling_stiffness * (device - bodies[0].position);
      if (k + 1 == travel + 50) {
        EXPECT_NEAR((spring + force).norm(), 0, 1e-3 * force.norm());
      }
    }
  }
  return force.norm();
}

// A rigid ball 11.5 mm deep, frictionless (a unique rest): the default solve is within 5 % of
// 128 substeps with 3 sweeps. With one stretch sweep the membrane's stretch rows keep the
// compliance alpha + w h^2 and read about 15 % soft: the comparison means something.
TEST(PressConvergence, RigidBallForceIsWithinFivePercentOfAFourTimesFinerSolve) {
  Press p;
  p.depth = Real(0.0115);
  const PressFigures f = press_three(p, 128, 3);
  EXPECT_GT(f.reference, 0.2);  // a few tenths of a newton: the membrane's stiff part
  EXPECT_NEAR(f.by_default, f.reference, 0.05 * f.reference);
  EXPECT_LT(f.one_sweep, 0.9 * f.reference);
  // The implicit membrane step (physics/implicit_membrane.hpp), one a 5 ms step, with the toe's
  // modulus throughout (the same material), presses the fascia as converged XPBD does:
  // measured 0.3293 against 0.3241 N (0.3175 N without the hinges).
  const Real implicit = implicit_press(tissue::default_fascia_membrane().youngs_modulus, 1, p);
  EXPECT_NEAR(implicit, f.reference, 0.02 * f.reference);
}

// The same press through the tool proxy (its coupling inside the solve), 12 mm deep: the tissue's
// force on the tool is within 5 % of the 4x finer solve (measured 0.3295 against 0.3367 N).
// Frictionless, as above; the frictional press follows.
TEST(PressConvergence, ProxyForceIsWithinFivePercentOfAFourTimesFinerSolve) {
  Press p;
  p.depth = Real(0.012);
  p.proxy = true;
  const Real by_default = press_force(p);
  Press fine = p;
  fine.substeps = 128, fine.stretch_sweeps = 3;
  const Real reference = press_force(fine);
  EXPECT_GT(reference, 0.2);
  EXPECT_NEAR(by_default, reference, 0.05 * reference);
  // The implicit membrane step with the proxy solved in the same system: measured 0.3417
  // against 0.3367 N.
  const Real implicit = implicit_press(tissue::default_fascia_membrane().youngs_modulus, 1, p);
  EXPECT_NEAR(implicit, reference, 0.02 * reference);
}

// Through the proxy with the tool's friction (the fascia's mu, 0.2): the coupling's compliance
// lets the membrane settle the same way at every setting, and the default is within 5 % of
// 256 x 3 (measured 0.3382 against 0.3454 N); one sweep reads 0.2833 N. A rigid ball with
// friction has no such rest: its force scattered by +-15 % between settings with no trend
// (docs/physics.md), so no test compares it.
TEST(PressConvergence, ProxyForceWithFrictionIsWithinFivePercentOfAFinerSolve) {
  Press p;
  p.depth = Real(0.012);
  p.proxy = true;
  p.friction = true;
  const PressFigures f = press_three(p, 256, 3);
  EXPECT_GT(f.reference, 0.2);
  EXPECT_NEAR(f.by_default, f.reference, 0.05 * f.reference);
  EXPECT_LT(f.one_sweep, 0.9 * f.reference);
}

// The implicit membrane step with the fascia's law (2.65 MPa past 5 % strain): the same ball
// meets far more.
TEST(PressConvergence, PastTheToeTheImplicitFasciaPushesBackHarder) {
  const Real toe = implicit_press(tissue::default_fascia_membrane().youngs_modulus, 1);
  const Real stiffening = implicit_press(Real(2.65e6), Real(0.05));
  // Measured 5.73 N against 0.329 N: the ball stretches the membrane well past its toe.
  EXPECT_GT(stiffening, 10 * toe);
}

}  // namespace
}  // namespace imasim
