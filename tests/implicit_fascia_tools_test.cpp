// The instruments on the implicit fascia (scene/implicit_mesh_scene.hpp): a proxy's contact row
// and a proxy's hold on a fascia vertex are solved with the fascia, the proxy a body of the solve
// on its coupling's spring and damper; the XPBD step then carries the fascia's force on the proxy,
// and the rows and holds get the implicit step's impulses, so the felt force reads them as it
// reads XPBD's. At rest the coupling carries what the fascia pushes or pulls with: k o = F.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "physics/executor.hpp"
#include "scene/thorax_scene.hpp"
#include "tissue/mesh_object.hpp"

namespace imasim::scene {
namespace {

constexpr Real kCoupling = 1000;  // the proxy's spring (unit: N/m), eq. 17's coupling
constexpr Real kDamping = 5;      // (unit: N s/m)

struct Rig {
  ThoraxScene scene;
  std::uint32_t particle = 0;     // the fascia's free vertex nearest its centroid
  Vec3 start = Vec3::Zero();      // where it rested
  Vec3 heartward = Vec3::Zero();  // unit, from it toward the heart's centre
};

Rig settled_rig() {
  ThoraxSceneParams params = default_thorax_scene_params();
  params.playback.beating = false;
  params.fascia_solver = std::string(kImplicitFasciaSolver);
  Rig rig{make_thorax_scene(params)};
  tissue::TissueWorld& w = rig.scene.patch.world;
  w.state.proxies.assign(1, physics::ProxyBody{});
  physics::Executor exec(1);
  for (int n = 0; n < 20; ++n)
    EXPECT_TRUE(step_thorax_scene(rig.scene, exec).ok());
  const tissue::MeshObject& fascia = w.meshes[rig.scene.patch.fascia];
  const physics::Particles& P = w.state.particles;
  Vec3 centroid = Vec3::Zero();
  for (std::uint32_t k = 0; k < fascia.particle_count; ++k)
    centroid += P.position[fascia.first_particle + k];
  centroid /= Real(fascia.particle_count);
  Real nearest = 1;
  for (std::uint32_t k = 0; k < fascia.particle_count; ++k) {
    const std::uint32_t p = fascia.first_particle + k;
    if (P.is_fixed(p) || (P.position[p] - centroid).norm() >= nearest) continue;
    nearest = (P.position[p] - centroid).norm();
    rig.particle = p;
  }
  rig.start = P.position[rig.particle];
  Vec3 heart = Vec3::Zero();
  for (const Vec3& v : rig.scene.heart.current)
    heart += v;
  heart /= Real(rig.scene.heart.current.size());
  rig.heartward = (heart - rig.start).normalized();
  return rig;
}

// The proxy as the session prepares it each step: the coupling, relaxed at the device, carrying
// the offset it ended the last step with.
void prepare_proxy(physics::ProxyBody& b) {
  b.stiffness = kCoupling;
  b.damping = kDamping;
  b.rest = Vec3::Zero();
}

TEST(ImplicitFasciaTools, AProxysHoldLiftsTheFasciaAndTheFasciaPullsTheProxyBack) {
  Rig rig = settled_rig();
  tissue::TissueWorld& w = rig.scene.patch.world;
  // The jaws 4 mm from where the vertex rested, towards the heart (a retraction), held there.
  const Vec3 jaws = rig.start + Real(0.004) * rig.heartward;
  physics::Executor exec(1);
  physics::StepProfile profile;
  for (int n = 0; n < 200; ++n) {  // 1 s
    prepare_thorax_step(rig.scene, profile, exec);
    physics::ProxyBody& body = w.state.proxies[0];
    prepare_proxy(body);
    // The hold's target rides on the tool where its proxy begins the step (grasp.cpp).
    w.state.body_attachments = {{rig.particle, 0, jaws + body.offset, Real(1e-6)}};
    ASSERT_TRUE(finish_thorax_step(rig.scene, exec).ok()) << "step " << n;
  }
  const Vec3 held = w.state.particles.position[rig.particle];
  const physics::ProxyBody& body = w.state.proxies[0];
  const Real dt = w.model.solver.dt;
  const Vec3 pull = physics::held_pull_on_body(w.state.body_attachments, 0, dt);
  // The vertex went with the jaws part of the way, the proxy gave the rest: one vertex drawn out
  // of the sheet strains its edges past the toe, where the law is 26 times stiffer (measured:
  // 1.24 mm, the pull 2.89 N).
  EXPECT_GT((held - rig.start).dot(rig.heartward), 0.001);
  EXPECT_LT((held - (jaws + body.offset)).norm(), 1e-5);  // the hold's stretch: pull / 1e6 N/m
  // The fascia pulls the jaws back, away from the heart, and at rest the coupling carries it.
  EXPECT_LT(pull.dot(rig.heartward), -1e-3);
  EXPECT_NEAR((kCoupling * body.offset - pull).norm(), 0, 0.02 * pull.norm());
  EXPECT_NEAR((body.impulse / dt - pull).norm(), 0, 0.02 * pull.norm());
  EXPECT_TRUE(rig.scene.implicit_fascia->last.ok);
  EXPECT_LT(rig.scene.implicit_fascia->last.residual, 1e-4);
}

TEST(ImplicitFasciaTools, AProxysContactPushesTheFasciaAndItsRowCarriesThePushBack) {
  Rig rig = settled_rig();
  tissue::TissueWorld& w = rig.scene.patch.world;
  // A tool surface 3 mm past where the vertex rested, away from the heart, facing the wall: it
  // presses the vertex 3 mm towards the chest wall, as the hook does (the plane's normal is out of
  // the tool).
  const Vec3 press = -rig.heartward;
  const Vec3 surface = rig.start + Real(0.003) * press;
  physics::Executor exec(1);
  physics::StepProfile profile;
  for (int n = 0; n < 200; ++n) {
    prepare_thorax_step(rig.scene, profile, exec);
    physics::ProxyBody& body = w.state.proxies[0];
    prepare_proxy(body);
    physics::ContactRow row;
    row.particle = rig.particle;
    row.tag = 16;
    row.point0 = row.point1 = surface + body.offset;
    row.normal = press;
    row.body = 0;
    w.state.contacts.rows.push_back(row);
    ASSERT_TRUE(finish_thorax_step(rig.scene, exec).ok()) << "step " << n;
  }
  const physics::ContactRow* row = nullptr;
  for (const physics::ContactRow& c : w.state.contacts.rows)
    if (c.tag == 16) row = &c;
  ASSERT_NE(row, nullptr);  // the row stays in the XPBD set, for the felt force to read
  const Real dt = w.model.solver.dt;
  const physics::ProxyBody& body = w.state.proxies[0];
  const Real push = row->normal_impulse / dt;  // on the vertex, along the normal (unit: N)
  EXPECT_GT(push, 1e-3);
  EXPECT_GT(row->depth, 0);  // touching: the contact events and the summary see it
  EXPECT_LT(row->depth, 1e-6);
  // The vertex went with the surface; the tool was pushed back by the fascia, and its coupling
  // carries that push at rest.
  const Vec3 x = w.state.particles.position[rig.particle];
  EXPECT_NEAR((x - (surface + body.offset)).dot(press), 0, 1e-6);
  EXPECT_GT((x - rig.start).dot(press), 0.001);
  EXPECT_NEAR((kCoupling * body.offset + push * press).norm(), 0, 0.02 * push);
  EXPECT_NEAR((body.impulse / dt + push * press).norm(), 0, 0.02 * push);
}

// The tool's surface pressing the vertex 3 mm towards the wall, as above, then drawn 1 mm along
// the sheet over 0.5 s. With the tissue's friction (mu 0.2, pressed by the last step's push) the
// vertex is dragged until the sheet's pull in its plane matches Coulomb's bound, and the surface
// slides on under it: the tool's coupling is held back by mu times its push. Without friction the
// surface slides under the vertex and nothing holds the tool back.
struct Drag {
  Real carried = 0;  // how far the vertex went along with the surface (unit: m)
  Real drag = 0;     // the coupling's pull along the draw at the end, k o . t (unit: N)
  Real push = 0;     // the row's push (unit: N)
};

Drag drag_along(Real mu) {
  Rig rig = settled_rig();
  tissue::TissueWorld& w = rig.scene.patch.world;
  const Vec3 press = -rig.heartward;
  const Vec3 along = press.unitOrthogonal();
  const Vec3 surface = rig.start + Real(0.003) * press;
  physics::Executor exec(1);
  physics::StepProfile profile;
  Vec3 pressed = Vec3::Zero();
  for (int n = 0; n < 200; ++n) {
    prepare_thorax_step(rig.scene, profile, exec);
    physics::ProxyBody& body = w.state.proxies[0];
    prepare_proxy(body);
    const Real drawn0 = Real(0.001) * std::clamp(Real(n - 100) / 100, Real(0), Real(1));
    const Real drawn1 = Real(0.001) * std::clamp(Real(n - 99) / 100, Real(0), Real(1));
    physics::ContactRow row;
    row.particle = rig.particle;
    row.tag = 16;
    row.point0 = surface + drawn0 * along + body.offset;
    row.point1 = surface + drawn1 * along + body.offset;
    row.normal = press;
    row.body = 0;
    row.static_friction = row.kinetic_friction = mu;
    w.state.contacts.rows.push_back(row);
    EXPECT_TRUE(finish_thorax_step(rig.scene, exec).ok()) << "step " << n;
    if (n == 99) pressed = w.state.particles.position[rig.particle];
  }
  Drag out;
  out.carried = (w.state.particles.position[rig.particle] - pressed).dot(along);
  out.drag = kCoupling * w.state.proxies[0].offset.dot(along);
  for (const physics::ContactRow& c : w.state.contacts.rows)
    if (c.tag == 16) out.push = c.normal_impulse / w.model.solver.dt;
  EXPECT_LT(rig.scene.implicit_fascia->last.residual, 1e-4);
  return out;
}

TEST(ImplicitFasciaTools, AProxysContactDragsTheFasciaAlongByItsFriction) {
  const Drag rubbed = drag_along(0.2);
  const Drag slid = drag_along(0);
  // Dragged a little: a vertex of the taut sheet resists in its plane by its edges' axial
  // stiffness (measured 56 um, the push 0.062 N).
  EXPECT_GT(rubbed.carried, 2e-5);
  EXPECT_LT(std::abs(slid.carried), 1e-9);
  // Sliding, the tool is held back by Coulomb's mu times its push (measured to 0.01 %).
  EXPECT_GT(rubbed.push, 0.01);
  EXPECT_NEAR(-rubbed.drag, 0.2 * rubbed.push, 0.02 * 0.2 * rubbed.push);
  EXPECT_LT(std::abs(slid.drag), 1e-9);
}

// The jaws drawing the fascia towards the heart, their proxy stopped 4.5 mm short of the device by
// a surface (the heart's stop): the implicit step stops the proxy there too, so the XPBD step,
// whose stop has the last word, does not move the proxy away from the vertex it holds: the vertex
// stays on the hold's target (measured without the implicit step's stop: tens of um off, each
// step).
TEST(ImplicitFasciaTools, AHoldOnAProxyStoppedByASurfaceStaysOnTheProxy) {
  Rig rig = settled_rig();
  tissue::TissueWorld& w = rig.scene.patch.world;
  const Vec3 jaws = rig.start + Real(0.006) * rig.heartward;
  const Vec3 surface = rig.start + Real(0.0015) * rig.heartward;
  physics::Executor exec(1);
  physics::StepProfile profile;
  Real largest_stretch = 0;
  for (int n = 0; n < 200; ++n) {
    prepare_thorax_step(rig.scene, profile, exec);
    physics::ProxyBody& body = w.state.proxies[0];
    prepare_proxy(body);
    w.state.body_attachments = {{rig.particle, 0, jaws + body.offset, Real(1e-6)}};
    physics::BodyStopRow stop;
    stop.body = 0;
    stop.point0 = stop.point1 = jaws + body.offset;  // the jaws' point on its gathered path
    stop.surface0 = stop.surface1 = surface;
    stop.normal = -rig.heartward;
    w.state.body_stops = {stop};
    ASSERT_TRUE(finish_thorax_step(rig.scene, exec).ok()) << "step " << n;
    if (n >= 100) {
      const Vec3 held = w.state.particles.position[rig.particle];
      largest_stretch = std::max(largest_stretch, (held - (jaws + body.offset)).norm());
    }
  }
  const physics::ProxyBody& body = w.state.proxies[0];
  // The jaws rest on the surface (the spring's 4.5 N more than the fascia's pull), 4.5 mm short of
  // the device, to within the hold's stretch (about 4.5 N / 1e6 N/m), and the vertex with them.
  EXPECT_NEAR(body.offset.dot(rig.heartward), -0.0045, 1e-5);
  EXPECT_LT(largest_stretch, 1e-5);  // the hold's stretch, pull / 1e6 N/m
  EXPECT_LT(rig.scene.implicit_fascia->last.residual, 1e-4);
}

}  // namespace
}  // namespace imasim::scene
