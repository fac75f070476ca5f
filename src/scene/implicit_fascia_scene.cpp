#include "scene/implicit_fascia_scene.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "physics/damping.hpp"
#include "scene/thorax_scene.hpp"
#include "tissue/fat_support.hpp"

namespace imasim::scene {

namespace {

// The fascia's XPBD distance and dihedral rows out of the constraint system, in the edges' order
// (the index is a hash map: sorted for determinism).
void remove_fascia_rows(tissue::TissueWorld& w, tissue::MeshObject& mesh) {
  std::vector<std::uint64_t> keys;
  for (const auto& [key, record] : mesh.edges)
    keys.push_back(key);
  std::sort(keys.begin(), keys.end());
  for (std::uint64_t key : keys) {
    tissue::EdgeRecord& record = mesh.edges[key];
    w.state.constraints.distance.remove(record.distance);
    w.state.constraints.dihedral.remove(record.dihedral);
    record.distance = {};
    record.dihedral = {};
  }
}

void stiffen_coagulated_edges(SceneImplicitFascia& f) {
  physics::ImplicitMembrane& membrane = *f.fascia.membrane;
  const std::span<const physics::MembraneEdge> edges = membrane.edges();
  for (std::size_t e = 0; e < edges.size(); ++e) {
    if (f.edge_stiffened[e]) continue;
    const physics::MembraneEdge& edge = edges[e];
    const bool i = edge.i < f.coagulated.size() && f.coagulated[edge.i];
    const bool j = edge.j < f.coagulated.size() && f.coagulated[edge.j];
    if (!i && !j) continue;
    membrane.scale_edge(e, f.coagulated_factor);
    f.edge_stiffened[e] = 1;
  }
}

void build_fascia_solver(ThoraxScene& scene, SceneImplicitFascia& f) {
  tissue::TissueWorld& w = scene.patch.world;
  const auto bodies = static_cast<std::uint32_t>(w.state.proxies.size());
  f.fascia = tissue::make_implicit_fascia(w, scene.patch.fascia, f.material, f.bending_stiffness,
                                          w.model.solver.dt, bodies);
  const tissue::MeshObject& mesh = w.meshes[scene.patch.fascia];
  f.inverse_mass.resize(mesh.particle_count);
  f.velocity.resize(mesh.particle_count);
  f.built_revision = mesh.topology_revision;
  f.built_bodies = bodies;
  f.bodies.resize(bodies);
  f.force_on_body.resize(bodies);
  f.touched.resize(bodies);
  f.edge_stiffened.assign(f.fascia.membrane->edges().size(), 0);
  stiffen_coagulated_edges(f);
}

// A hold of compliance 0 (rigid in XPBD) as the implicit step's spring (unit: N/m): 1 um for 1 N.
constexpr Real kRigidHoldStiffness = Real(1e6);

// An instrument's row on the fascia, while the XPBD step runs: its tag is this bit and its index.
constexpr std::uint32_t kImplicitRowMark = 0x80000000u;

bool moves_proxy(const std::vector<physics::ProxyBody>& proxies, std::uint32_t body) {
  return body < proxies.size() && proxies[body].active();
}

bool pressed_before(const SceneImplicitFascia::PressedVertex& a,
                    const SceneImplicitFascia::PressedVertex& b) {
  return a.vertex != b.vertex ? a.vertex < b.vertex : a.tag < b.tag;
}

// A row on the fascia as the implicit step's contact: its plane at the step's end, out by the
// margin; the surface's motion over the step and its kinetic friction, pressed by the force the
// last step left between the vertex and that surface (friction's lagged normal force).
void add_contact(SceneImplicitFascia& f, const physics::ContactRow& c, std::uint32_t first) {
  const std::uint32_t vertex = c.particle - first;
  const SceneImplicitFascia::PressedVertex key{vertex, c.tag};
  const auto found = std::lower_bound(f.pressed.begin(), f.pressed.end(), key, pressed_before);
  const bool pressed = found != f.pressed.end() && found->vertex == vertex && found->tag == c.tag;
  f.contacts.push_back({vertex, c.point1 + c.margin * c.normal, c.normal, c.body,
                        c.point1 - c.point0, c.kinetic_friction, pressed ? found->force : 0});
  f.contact_tags.push_back(c.tag);
}

// The force each vertex ended pressed with by each surface, for the next step's friction.
void keep_pressed(SceneImplicitFascia& f) {
  const std::span<const Real> force = f.fascia.membrane->contact_forces();
  f.pressed.clear();
  for (std::size_t k = 0; k < f.contacts.size(); ++k)
    if (force[k] > 0) f.pressed.push_back({f.contacts[k].vertex, f.contact_tags[k], force[k]});
  std::sort(f.pressed.begin(), f.pressed.end(), pressed_before);
}

// The instruments' rows and holds on the fascia, and their proxies, as the implicit step's
// bodies; the fixed planes were taken already.
void gather_instruments(tissue::TissueWorld& w, SceneImplicitFascia& f, std::uint32_t first,
                        std::uint32_t end) {
  const std::vector<physics::ProxyBody>& proxies = w.state.proxies;
  for (std::uint32_t b = 0; b < f.bodies.size(); ++b) {
    const physics::ProxyBody& p = proxies[b];
    // An idle proxy is a body all the same (the solver's rows are fixed at set-up), held where it
    // is by a unit spring: no contact names it.
    f.bodies[b] = p.active() ? physics::MembraneBody{p.rest, p.stiffness, p.damping, p.offset}
                             : physics::MembraneBody{p.offset, 1, 0, p.offset};
  }
  // The rows on the fascia that stay are the proxies' (the fixed planes were taken out before).
  // The XPBD step reorders its rows (by rate band), so each is marked with its index here in
  // its tag, which the step does not read, and found by it after.
  f.tool_tags.clear();
  for (physics::ContactRow& c : w.state.contacts.rows) {
    if (c.particle < first || c.particle >= end) continue;
    add_contact(f, c, first);
    const auto index = static_cast<std::uint32_t>(f.tool_tags.size());
    f.tool_tags.push_back(c.tag);
    c.tag = kImplicitRowMark | index;
    c.stops_body = true;
  }
  f.attachments.clear();
  for (physics::BodyAttachmentRow& r : w.state.body_attachments) {
    if (r.particle < first || r.particle >= end || !moves_proxy(proxies, r.body)) continue;
    const Real k = r.compliance > 0 ? 1 / r.compliance : kRigidHoldStiffness;
    f.attachments.push_back({r.particle - first, r.target, r.body, k});
    r.holds_body = true;
  }
  // The surfaces that stop the proxies, as the XPBD step will find them at its end (the body
  // where it starts: the offset not yet carried).
  f.body_stops.clear();
  for (const physics::BodyStopRow& r : w.state.body_stops) {
    if (!moves_proxy(proxies, r.body)) continue;
    f.body_stops.push_back({r.body, r.normal, r.normal.dot(r.point1 - r.surface1) - r.margin});
  }
}

// What the step left on each proxy: its rows' push (each contact's force, normal to its plane),
// its holds' pull, summed per body and added to the proxy's spring for the XPBD step.
void load_proxies(tissue::TissueWorld& w, SceneImplicitFascia& f, std::uint32_t first,
                  std::size_t fixed_planes) {
  const std::span<const Real> force = f.fascia.membrane->contact_forces();
  const physics::Particles& P = w.state.particles;
  std::fill(f.force_on_body.begin(), f.force_on_body.end(), Vec3::Zero());
  std::fill(f.touched.begin(), f.touched.end(), 0);
  f.tool_depth.resize(f.tool_tags.size());
  for (std::size_t k = 0; k < f.tool_tags.size(); ++k) {
    const physics::MembraneContact& c = f.contacts[fixed_planes + k];
    const Vec3 moved = f.bodies[c.body].position - w.state.proxies[c.body].offset;
    const Real gap = c.normal.dot(P.position[first + c.vertex] - c.point - moved);
    f.tool_depth[k] = force[fixed_planes + k] > 0 ? std::max(Real(0), -gap) : Real(0);
    const Vec3& rub = f.fascia.membrane->contact_frictions()[fixed_planes + k];
    // The vertex got +F n and the friction: the body the opposite.
    f.force_on_body[c.body] -= force[fixed_planes + k] * c.normal + rub;
    f.touched[c.body] = f.touched[c.body] || force[fixed_planes + k] > 0 || rub != Vec3::Zero();
  }
  f.attachment_pull.resize(f.attachments.size());
  for (std::size_t k = 0; k < f.attachments.size(); ++k) {
    const physics::MembraneAttachment& a = f.attachments[k];
    const Vec3 moved = f.bodies[a.body].position - w.state.proxies[a.body].offset;
    f.attachment_pull[k] = physics::attachment_pull(a, P.position[first + a.vertex], moved);
    f.force_on_body[a.body] += f.attachment_pull[k];
    f.touched[a.body] = 1;
  }
  // A proxy the fascia touched is carried by the XPBD step where the implicit step left it, o1,
  // unless something more (the vessel, the fat, the heart's stop) acts on it there: its spring's
  // rest is put where the XPBD step's substeps of the coupling alone (each an implicit Euler step,
  // o - rest shrinking by r_s = c / (c + k h_s)) carry o0 to o1. At rest (o0 = o1) that is
  // F / k, the fascia's force added to the spring.
  const Real substeps = Real(w.model.solver.substeps);
  const Real h = w.model.solver.dt / substeps;
  for (std::uint32_t b = 0; b < f.bodies.size(); ++b) {
    physics::ProxyBody& p = w.state.proxies[b];
    if (!p.active() || !f.touched[b]) continue;
    const Real r = std::pow(p.damping / (p.damping + p.stiffness * h), substeps);
    p.rest = (f.bodies[b].position - r * p.offset) / (1 - r);
  }
}

// Eq. 4 on the step's velocities, as the XPBD step damps its objects' (physics/damping.hpp): the
// share k_l of every velocity and k_c of the non-rigid motion removed per 5 ms. Over one step
// of dt the same shares as over its substeps.
void damp_fascia(tissue::TissueWorld& w, const tissue::MeshObject& mesh) {
  const Real dt = w.model.solver.dt;
  const physics::ObjectParams& object = w.model.objects[mesh.object];
  physics::Particles& P = w.state.particles;
  const Real keep = physics::damping_keep(object.linear_damping, dt);
  const std::uint32_t first = mesh.first_particle, end = first + mesh.particle_count;
  for (std::uint32_t p = first; p < end; ++p)
    if (P.inverse_mass[p] > 0) P.velocity[p] *= keep;
  // The angular pass reads the object's dynamic range as a step finds it; the XPBD step, which
  // saw the fascia kinematic, finds it again.
  physics::ObjectRange& range = w.state.scratch.object_ranges[mesh.object];
  const physics::ObjectRange kept = range;
  range = {first, end};
  physics::apply_angular_damping(w.model, w.state, mesh.object, dt);
  range = kept;
}

}  // namespace

void use_implicit_fascia(ThoraxScene& scene, const physics::StiffeningMembrane& material) {
  tissue::TissueWorld& w = scene.patch.world;
  tissue::MeshObject& mesh = w.meshes[scene.patch.fascia];
  const physics::ConstraintMaterial& bend = w.model.materials[mesh.bend_material];
  if (!(bend.compliance > 0))
    throw std::invalid_argument("implicit fascia: the fascia's bending has no stiffness to take");
  SceneImplicitFascia f;
  f.material = material;
  f.bending_stiffness = 1 / bend.compliance;
  build_fascia_solver(scene, f);
  remove_fascia_rows(w, mesh);
  mesh.rows_in_xpbd = false;
  // Sized for the spare vertices cuts bring in, so that a step after a cut allocates nothing.
  f.contacts.reserve(w.state.contacts.rows.capacity());
  f.tool_tags.reserve(w.state.contacts.rows.capacity());
  f.tool_depth.reserve(w.state.contacts.rows.capacity());
  f.contact_tags.reserve(w.state.contacts.rows.capacity());
  f.pressed.reserve(w.state.contacts.rows.capacity());
  f.attachments.reserve(mesh.particle_capacity);
  f.attachment_pull.reserve(mesh.particle_capacity);
  f.body_stops.reserve(w.state.body_stops.capacity());
  f.supports.reserve(w.state.supports.capacity());
  f.inverse_mass.reserve(mesh.particle_capacity);
  f.velocity.reserve(mesh.particle_capacity);
  f.coagulated.reserve(mesh.particle_capacity);
  scene.implicit_fascia = std::move(f);
}

void refit_scene_fascia(ThoraxScene& scene) {
  if (!scene.implicit_fascia) return;
  tissue::TissueWorld& w = scene.patch.world;
  remove_fascia_rows(w, w.meshes[scene.patch.fascia]);
  build_fascia_solver(scene, *scene.implicit_fascia);
  ++scene.implicit_fascia->refits;
}

void coagulate_scene_fascia(ThoraxScene& scene, std::span<const std::uint8_t> coagulated,
                            Real factor) {
  if (!scene.implicit_fascia) return;
  SceneImplicitFascia& f = *scene.implicit_fascia;
  const tissue::MeshObject& mesh = scene.patch.world.meshes[scene.patch.fascia];
  f.coagulated_factor = factor;
  f.coagulated.resize(mesh.particle_count, 0);
  bool more = false;
  for (std::uint32_t k = 0; k < mesh.particle_count; ++k) {
    const std::uint32_t p = mesh.first_particle + k;
    const std::uint8_t now = p < coagulated.size() ? coagulated[p] : 0;
    more = more || (now && !f.coagulated[k]);
    f.coagulated[k] = now;
  }
  // A solver built before a cut is refitted by the step, which stiffens its edges then.
  if (more && f.built_revision == mesh.topology_revision) stiffen_coagulated_edges(f);
}

physics::StepResult step_scene_fascia(ThoraxScene& scene) {
  physics::StepResult result;
  if (!scene.implicit_fascia) return result;
  SceneImplicitFascia& f = *scene.implicit_fascia;
  tissue::TissueWorld& w = scene.patch.world;
  const tissue::MeshObject& mesh = w.meshes[scene.patch.fascia];
  // Cut since, or the instruments' proxies set up since.
  if (mesh.topology_revision != f.built_revision || f.built_bodies != w.state.proxies.size())
    refit_scene_fascia(scene);
  const std::uint32_t first = mesh.first_particle, end = first + mesh.particle_count;
  auto fixed_plane = [&](const physics::ContactRow& c) {
    return c.particle >= first && c.particle < end && !moves_proxy(w.state.proxies, c.body);
  };
  f.contacts.clear();
  f.contact_tags.clear();
  for (const physics::ContactRow& c : w.state.contacts.rows)
    if (fixed_plane(c)) add_contact(f, c, first);
  std::erase_if(w.state.contacts.rows, fixed_plane);
  const std::size_t fixed_planes = f.contacts.size();
  gather_instruments(w, f, first, end);
  // The fat's columns under the fascia (the XPBD step gathers its own after, the fascia then
  // kinematic in it).
  tissue::gather_fat_supports(w);
  f.supports.clear();
  for (const physics::SupportRow& r : w.state.supports) {
    if (r.particle < first || r.particle >= end) continue;
    f.supports.push_back(
        {r.particle - first, r.offset * r.normal, r.normal, 1 / r.compliance, r.pushes_only});
  }
  f.last =
      tissue::step_implicit_fascia(f.fascia, w, w.model.objects[mesh.object].gravity, f.contacts,
                                   f.bodies, f.solve, f.attachments, f.body_stops, f.supports);
  load_proxies(w, f, first, fixed_planes);
  keep_pressed(f);
  damp_fascia(w, mesh);
  f.unsolved_steps += f.last.residual > f.solve.tolerance;
  ++f.steps;
  f.iterations += f.last.iterations;
  f.factorizations += f.last.factorizations;
  f.active_set_factorizations += f.last.active_set_factorizations;
  f.shortened_iterations += f.last.shortened_iterations;
  f.largest_residual = std::max(f.largest_residual, f.last.residual);
  if (!f.last.ok) {
    result.status = physics::StepStatus::non_finite;
    result.particle = first;
  }
  physics::Particles& P = w.state.particles;
  for (std::uint32_t k = 0; k < mesh.particle_count; ++k) {
    f.inverse_mass[k] = P.inverse_mass[first + k];
    f.velocity[k] = P.velocity[first + k];
    P.inverse_mass[first + k] = 0;
  }
  return result;
}

void release_scene_fascia(ThoraxScene& scene) {
  if (!scene.implicit_fascia) return;
  SceneImplicitFascia& f = *scene.implicit_fascia;
  const tissue::MeshObject& mesh = scene.patch.world.meshes[scene.patch.fascia];
  physics::Particles& P = scene.patch.world.state.particles;
  for (std::uint32_t k = 0; k < mesh.particle_count; ++k) {
    P.inverse_mass[mesh.first_particle + k] = f.inverse_mass[k];
    P.velocity[mesh.first_particle + k] = f.velocity[k];
  }
  // The rows and holds did nothing in XPBD (their particles had no mass): the implicit step's
  // impulses over the step are theirs, and their proxies'.
  physics::State& state = scene.patch.world.state;
  const Real dt = scene.patch.world.model.solver.dt;
  const std::span<const Real> force = f.fascia.membrane->contact_forces();
  const std::size_t fixed_planes = f.contacts.size() - f.tool_tags.size();
  for (physics::ContactRow& row : state.contacts.rows) {
    if (!(row.tag & kImplicitRowMark)) continue;
    const std::uint32_t k = row.tag & ~kImplicitRowMark;
    row.tag = f.tool_tags[k];
    row.stops_body = false;
    row.normal_impulse = force[fixed_planes + k] * dt;
    row.depth = f.tool_depth[k];
  }
  // A grasper holds a particle once: its hold is found by particle and body.
  for (physics::BodyAttachmentRow& r : state.body_attachments) {
    if (r.particle < mesh.first_particle || r.particle >= mesh.first_particle + mesh.particle_count)
      continue;
    r.holds_body = false;
    for (std::size_t k = 0; k < f.attachments.size(); ++k) {
      const physics::MembraneAttachment& a = f.attachments[k];
      if (a.vertex + mesh.first_particle == r.particle && a.body == r.body)
        r.impulse = f.attachment_pull[k] * dt;
    }
  }
  for (std::uint32_t b = 0; b < f.bodies.size(); ++b)
    if (state.proxies[b].active()) state.proxies[b].impulse += f.force_on_body[b] * dt;
}

}  // namespace imasim::scene
