#include "scene/implicit_mesh_scene.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "physics/damping.hpp"
#include "scene/thorax_scene.hpp"
#include "tissue/coupling.hpp"
#include "tissue/fat_support.hpp"
#include "tissue/tissue_step.hpp"

namespace imasim::scene {

namespace {

// The fascia's XPBD distance and dihedral rows out of the constraint system, in the edges' order
// (the index is a hash map: sorted for determinism).
void remove_indexed_rows(tissue::TissueWorld& w, tissue::MeshObject& mesh) {
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

// A mesh without an edge index (the vessel: never cut): every distance and dihedral row with a
// particle of it out of the constraint system, in the rows' order as they are found.
void remove_rows_touching(tissue::TissueWorld& w, const tissue::MeshObject& mesh) {
  const std::uint32_t first = mesh.first_particle, end = first + mesh.particle_count;
  auto of_mesh = [&](std::uint32_t p) { return p >= first && p < end; };
  physics::ConstraintSystem& cs = w.state.constraints;
  std::vector<physics::DistanceHandle> distances;
  for (const auto& group : cs.distance.groups())
    for (const physics::DistanceRow& r : group.rows)
      if (of_mesh(r.i) || of_mesh(r.j)) distances.push_back(cs.distance.handle_of(r));
  std::vector<physics::DihedralHandle> dihedrals;
  for (const auto& group : cs.dihedral.groups())
    for (const physics::DihedralRow& r : group.rows)
      if (std::any_of(r.p.begin(), r.p.end(), of_mesh))
        dihedrals.push_back(cs.dihedral.handle_of(r));
  for (physics::DistanceHandle h : distances)
    cs.distance.remove(h);
  for (physics::DihedralHandle h : dihedrals)
    cs.dihedral.remove(h);
}

void stiffen_coagulated_edges(SceneImplicitMesh& f) {
  physics::ImplicitMembrane& membrane = *f.solver.membrane;
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

void build_solver(ThoraxScene& scene, SceneImplicitMesh& f) {
  tissue::TissueWorld& w = scene.patch.world;
  const auto bodies = static_cast<std::uint32_t>(w.state.proxies.size());
  const Real h = w.model.solver.dt;
  const tissue::MeshObject& mesh = w.meshes[f.mesh];
  if (f.own_rows) {
    f.solver.mesh = f.mesh;
    f.solver.membrane.emplace(tissue::implicit_membrane_of_rows(w, f.rows, h, bodies));
    f.solver.x.resize(mesh.particle_count);
    f.solver.v.resize(mesh.particle_count);
  } else {
    f.solver = tissue::make_implicit_fascia(w, f.mesh, f.material, f.bending_stiffness, h, bodies);
  }
  f.inverse_mass.resize(mesh.particle_count);
  f.velocity.resize(mesh.particle_count);
  f.built_revision = mesh.topology_revision;
  f.built_bodies = bodies;
  f.bodies.resize(bodies);
  f.force_on_body.resize(bodies);
  f.touched.resize(bodies);
  f.edge_stiffened.assign(f.solver.membrane->edges().size(), 0);
  stiffen_coagulated_edges(f);
}

// Set-up of either mesh: its rows out of XPBD, the solver built, the scratch sized for the
// spare vertices cuts bring in, so that a step after a cut allocates nothing.
SceneImplicitMesh make_scene_mesh(ThoraxScene& scene, SceneImplicitMesh f) {
  tissue::TissueWorld& w = scene.patch.world;
  tissue::MeshObject& mesh = w.meshes[f.mesh];
  build_solver(scene, f);
  if (f.own_rows)
    remove_rows_touching(w, mesh);
  else
    remove_indexed_rows(w, mesh);
  mesh.rows_in_xpbd = false;
  f.contacts.reserve(w.state.contacts.rows.capacity());
  f.tool_tags.reserve(w.state.contacts.rows.capacity());
  f.tool_depth.reserve(w.state.contacts.rows.capacity());
  f.contact_tags.reserve(w.state.contacts.rows.capacity());
  f.pressed.reserve(w.state.contacts.rows.capacity());
  f.attachments.reserve(2 * mesh.particle_capacity);
  f.attachment_pull.reserve(2 * mesh.particle_capacity);
  f.body_stops.reserve(w.state.body_stops.capacity());
  f.supports.reserve(w.state.supports.capacity());
  f.inverse_mass.reserve(mesh.particle_capacity);
  f.velocity.reserve(mesh.particle_capacity);
  f.coagulated.reserve(mesh.particle_capacity);
  return f;
}

void refit(ThoraxScene& scene, SceneImplicitMesh& f) {
  tissue::TissueWorld& w = scene.patch.world;
  // A cut added XPBD rows to the fascia's edge index; the vessel's rows were read once.
  if (!f.own_rows) remove_indexed_rows(w, w.meshes[f.mesh]);
  build_solver(scene, f);
  ++f.refits;
}

// The largest force imbalance at a vessel's vertex its Newton solve leaves (unit: N).
constexpr Real kVesselTolerance = Real(1e-5);

// A hold of compliance 0 (rigid in XPBD) as the implicit step's spring (unit: N/m): 1 um for 1 N.
constexpr Real kRigidHoldStiffness = Real(1e6);

// An instrument's row on an implicit mesh, while the XPBD step runs: its tag is this bit and its
// index among that mesh's rows (the rows of each mesh are told apart by their particle).
constexpr std::uint32_t kImplicitRowMark = 0x80000000u;

bool moves_proxy(const std::vector<physics::ProxyBody>& proxies, std::uint32_t body) {
  return body < proxies.size() && proxies[body].active();
}

bool pressed_before(const SceneImplicitMesh::PressedVertex& a,
                    const SceneImplicitMesh::PressedVertex& b) {
  return a.vertex != b.vertex ? a.vertex < b.vertex : a.tag < b.tag;
}

// A row on the mesh as the implicit step's contact: its plane at the step's end, out by the
// margin; the surface's motion over the step and its kinetic friction, pressed by the force the
// last step left between the vertex and that surface (friction's lagged normal force).
void add_contact(SceneImplicitMesh& f, const physics::ContactRow& c, std::uint32_t first) {
  const std::uint32_t vertex = c.particle - first;
  const SceneImplicitMesh::PressedVertex key{vertex, c.tag};
  const auto found = std::lower_bound(f.pressed.begin(), f.pressed.end(), key, pressed_before);
  const bool pressed = found != f.pressed.end() && found->vertex == vertex && found->tag == c.tag;
  f.contacts.push_back({vertex, c.point1 + c.margin * c.normal, c.normal, c.body,
                        c.point1 - c.point0, c.kinetic_friction, pressed ? found->force : 0});
  f.contact_tags.push_back(c.tag);
}

// The force each vertex ended pressed with by each surface, for the next step's friction.
void keep_pressed(SceneImplicitMesh& f) {
  const std::span<const Real> force = f.solver.membrane->contact_forces();
  f.pressed.clear();
  for (std::size_t k = 0; k < f.contacts.size(); ++k)
    if (force[k] > 0) f.pressed.push_back({f.contacts[k].vertex, f.contact_tags[k], force[k]});
  std::sort(f.pressed.begin(), f.pressed.end(), pressed_before);
}

// The instruments' rows and holds on the mesh, and their proxies, as the implicit step's
// bodies; the fixed planes were taken already.
void gather_instruments(tissue::TissueWorld& w, SceneImplicitMesh& f, std::uint32_t first,
                        std::uint32_t end) {
  const std::vector<physics::ProxyBody>& proxies = w.state.proxies;
  // The rows on the mesh that stay are the proxies' (the fixed planes were taken out before).
  // The XPBD step reorders its rows (by rate band), so each is marked with its index here in
  // its tag, which the step does not read, and found by it after.
  std::fill(f.touched.begin(), f.touched.end(), 0);  // here: whether a row or hold names it
  f.tool_tags.clear();
  for (physics::ContactRow& c : w.state.contacts.rows) {
    if (c.particle < first || c.particle >= end) continue;
    add_contact(f, c, first);
    const auto index = static_cast<std::uint32_t>(f.tool_tags.size());
    f.tool_tags.push_back(c.tag);
    c.tag = kImplicitRowMark | index;
    c.stops_body = true;
    if (c.body < f.touched.size()) f.touched[c.body] = 1;
  }
  f.attachments.clear();
  for (physics::BodyAttachmentRow& r : w.state.body_attachments) {
    if (r.particle < first || r.particle >= end || !moves_proxy(proxies, r.body)) continue;
    const Real k = r.compliance > 0 ? 1 / r.compliance : kRigidHoldStiffness;
    f.attachments.push_back({r.particle - first, r.target, r.body, k});
    r.holds_body = true;
    f.touched[r.body] = 1;
  }
  f.tool_holds = f.attachments.size();
  // A proxy with a row or a hold on the mesh is a body of its solve, with the surfaces that stop
  // it as the XPBD step will find them at its end (the body where it starts: the offset not yet
  // carried). Any other is a body all the same (the solver's rows are fixed at set-up), held
  // where it is by a unit spring: solving its own motion here would only cost iterations, and
  // the XPBD step moves it.
  for (std::uint32_t b = 0; b < f.bodies.size(); ++b) {
    const physics::ProxyBody& p = proxies[b];
    f.bodies[b] = p.active() && f.touched[b]
                      ? physics::MembraneBody{p.rest, p.stiffness, p.damping, p.offset}
                      : physics::MembraneBody{p.offset, 1, 0, p.offset};
  }
  f.body_stops.clear();
  for (const physics::BodyStopRow& r : w.state.body_stops) {
    if (!moves_proxy(proxies, r.body) || !f.touched[r.body]) continue;
    f.body_stops.push_back({r.body, r.normal, r.normal.dot(r.point1 - r.surface1) - r.margin});
  }
}

// Eq. 9 where the mesh is the destination of a coupling:
// - beta = 1 (a strand an instrument holds): each vertex coupled to it is pulled to the
//   coupling's target (the source where the step begins), as XPBD's follow row puts it there,
//   here a stiff hold;
// - beta = 0: the vertex's offset from its reference decays by c.decay (0.8) a step. For a lone
//   vertex that is the backward-Euler step of a spring to the reference
//   (tissue::decay_spring_stiffness), which the solve takes with the rest: the rows resist it as
//   they resist any load. (Applied after the step, as the
//   XPBD step applies it to its own particles, it moved the coupled vertices against the rows
//   that the next solve then spent seven Newton iterations a step restoring; docs/physics.md.)
//   The reference moves with the heart's drive (tissue/heart_field.hpp): this is how the heart's
//   motion reaches the vessel.
void gather_couplings(tissue::TissueWorld& w, SceneImplicitMesh& f, std::uint32_t first,
                      std::uint32_t end) {
  const tissue::CouplingFlags flags{w.held, w.manipulated};
  const physics::Particles& P = w.state.particles;
  const Real h = w.model.solver.dt;
  for (const tissue::OffsetCoupling& c : w.couplings) {
    for (const auto& [j, i] : c.pairs) {
      if (i < first || i >= end || P.is_fixed(i) || tissue::destination_left(c, i, flags)) continue;
      if (tissue::pair_follows(c, j, flags)) {
        const Vec3 target = tissue::follow_target(c, P.position[j], w.reference[j], w.reference[i]);
        f.attachments.push_back({i - first, target, physics::kNoMembraneBody, kRigidHoldStiffness});
      } else if (c.decay < 1) {
        const Real k = tissue::decay_spring_stiffness(c, 1 / P.inverse_mass[i], h);
        f.attachments.push_back({i - first, w.reference[i], physics::kNoMembraneBody, k});
      }
    }
  }
}

// What the step left on each proxy: its rows' push (each contact's force, normal to its plane),
// its holds' pull, summed per body and added to the proxy's spring for the XPBD step.
void load_proxies(tissue::TissueWorld& w, SceneImplicitMesh& f, std::uint32_t first,
                  std::size_t fixed_planes) {
  const std::span<const Real> force = f.solver.membrane->contact_forces();
  const physics::Particles& P = w.state.particles;
  std::fill(f.force_on_body.begin(), f.force_on_body.end(), Vec3::Zero());
  std::fill(f.touched.begin(), f.touched.end(), 0);
  f.tool_depth.resize(f.tool_tags.size());
  for (std::size_t k = 0; k < f.tool_tags.size(); ++k) {
    const physics::MembraneContact& c = f.contacts[fixed_planes + k];
    const Vec3 moved = f.bodies[c.body].position - w.state.proxies[c.body].offset;
    const Real gap = c.normal.dot(P.position[first + c.vertex] - c.point - moved);
    f.tool_depth[k] = force[fixed_planes + k] > 0 ? std::max(Real(0), -gap) : Real(0);
    const Vec3& rub = f.solver.membrane->contact_frictions()[fixed_planes + k];
    // The vertex got +F n and the friction: the body the opposite.
    f.force_on_body[c.body] -= force[fixed_planes + k] * c.normal + rub;
    f.touched[c.body] = f.touched[c.body] || force[fixed_planes + k] > 0 || rub != Vec3::Zero();
  }
  f.attachment_pull.resize(f.tool_holds);
  for (std::size_t k = 0; k < f.tool_holds; ++k) {
    const physics::MembraneAttachment& a = f.attachments[k];
    const Vec3 moved = f.bodies[a.body].position - w.state.proxies[a.body].offset;
    f.attachment_pull[k] = physics::attachment_pull(a, P.position[first + a.vertex], moved);
    f.force_on_body[a.body] += f.attachment_pull[k];
    f.touched[a.body] = 1;
  }
  // A proxy the mesh touched is carried by the XPBD step where the implicit step left it, o1,
  // unless something more (the other tissues, the heart's stop) acts on it there: its spring's
  // rest is put where the XPBD step's substeps of the coupling alone (each an implicit Euler step,
  // o - rest shrinking by r_s = c / (c + k h_s)) carry o0 to o1. At rest (o0 = o1) that is
  // F / k, the mesh's force added to the spring.
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
void damp_mesh(tissue::TissueWorld& w, const tissue::MeshObject& mesh) {
  const Real dt = w.model.solver.dt;
  const physics::ObjectParams& object = w.model.objects[mesh.object];
  physics::Particles& P = w.state.particles;
  const Real keep = physics::damping_keep(object.linear_damping, dt);
  const std::uint32_t first = mesh.first_particle, end = first + mesh.particle_count;
  for (std::uint32_t p = first; p < end; ++p)
    if (P.inverse_mass[p] > 0) P.velocity[p] *= keep;
  // The angular pass reads the object's dynamic range as a step finds it; the XPBD step, which
  // saw the mesh kinematic, finds it again.
  physics::ObjectRange& range = w.state.scratch.object_ranges[mesh.object];
  const physics::ObjectRange kept = range;
  range = {first, end};
  physics::apply_angular_damping(w.model, w.state, mesh.object, dt);
  range = kept;
}

physics::StepResult step_mesh(ThoraxScene& scene, SceneImplicitMesh& f,
                              const physics::Executor& exec) {
  physics::StepResult result;
  tissue::TissueWorld& w = scene.patch.world;
  const tissue::MeshObject& mesh = w.meshes[f.mesh];
  // Cut since, or the instruments' proxies set up since.
  if (mesh.topology_revision != f.built_revision || f.built_bodies != w.state.proxies.size())
    refit(scene, f);
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
  gather_couplings(w, f, first, end);
  // The fat's columns under the mesh (gathered by step_scene_implicit; the XPBD step gathers its
  // own after, the mesh then kinematic in it).
  f.supports.clear();
  for (const physics::SupportRow& r : w.state.supports) {
    if (r.particle < first || r.particle >= end) continue;
    f.supports.push_back(
        {r.particle - first, r.offset * r.normal, r.normal, 1 / r.compliance, r.pushes_only});
  }
  f.last = tissue::step_implicit_fascia(f.solver, w, exec, w.model.objects[mesh.object].gravity,
                                        f.contacts, f.bodies, f.solve, f.attachments, f.body_stops,
                                        f.supports);
  load_proxies(w, f, first, fixed_planes);
  keep_pressed(f);
  damp_mesh(w, mesh);
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

void release_mesh(ThoraxScene& scene, SceneImplicitMesh& f) {
  tissue::TissueWorld& w = scene.patch.world;
  const tissue::MeshObject& mesh = w.meshes[f.mesh];
  const std::uint32_t first = mesh.first_particle, end = first + mesh.particle_count;
  physics::Particles& P = w.state.particles;
  for (std::uint32_t k = 0; k < mesh.particle_count; ++k) {
    P.inverse_mass[first + k] = f.inverse_mass[k];
    P.velocity[first + k] = f.velocity[k];
  }
  // The rows and holds did nothing in XPBD (their particles had no mass): the implicit step's
  // impulses over the step are theirs, and their proxies'.
  physics::State& state = w.state;
  const Real dt = w.model.solver.dt;
  const std::span<const Real> force = f.solver.membrane->contact_forces();
  const std::size_t fixed_planes = f.contacts.size() - f.tool_tags.size();
  for (physics::ContactRow& row : state.contacts.rows) {
    if (!(row.tag & kImplicitRowMark) || row.particle < first || row.particle >= end) continue;
    const std::uint32_t k = row.tag & ~kImplicitRowMark;
    row.tag = f.tool_tags[k];
    row.stops_body = false;
    row.normal_impulse = force[fixed_planes + k] * dt;
    row.depth = f.tool_depth[k];
  }
  // A grasper holds a particle once: its hold is found by particle and body.
  for (physics::BodyAttachmentRow& r : state.body_attachments) {
    if (r.particle < first || r.particle >= end) continue;
    r.holds_body = false;
    for (std::size_t k = 0; k < f.tool_holds; ++k) {
      const physics::MembraneAttachment& a = f.attachments[k];
      if (a.vertex + first == r.particle && a.body == r.body) r.impulse = f.attachment_pull[k] * dt;
    }
  }
  for (std::uint32_t b = 0; b < f.bodies.size(); ++b)
    if (state.proxies[b].active()) state.proxies[b].impulse += f.force_on_body[b] * dt;
}

}  // namespace

void use_implicit_fascia(ThoraxScene& scene, const physics::StiffeningMembrane& material) {
  tissue::TissueWorld& w = scene.patch.world;
  const tissue::MeshObject& mesh = w.meshes[scene.patch.fascia];
  const physics::ConstraintMaterial& bend = w.model.materials[mesh.bend_material];
  if (!(bend.compliance > 0))
    throw std::invalid_argument("implicit fascia: the fascia's bending has no stiffness to take");
  SceneImplicitMesh f;
  f.mesh = scene.patch.fascia;
  f.material = material;
  f.bending_stiffness = 1 / bend.compliance;
  scene.implicit_fascia = make_scene_mesh(scene, std::move(f));
}

void use_implicit_vessel(ThoraxScene& scene) {
  SceneImplicitMesh f;
  f.mesh = scene.patch.ima;
  f.own_rows = true;
  f.rows = tissue::rows_of_mesh(scene.patch.world, f.mesh);
  // Solved to 1e-5 N at a vertex (the fascia's 1e-6): the hook's press on it and its motion over
  // a beat are the same to five digits, in one Newton iteration a step against two.
  f.solve.tolerance = kVesselTolerance;
  scene.implicit_vessel = make_scene_mesh(scene, std::move(f));
}

void refit_scene_fascia(ThoraxScene& scene) {
  if (scene.implicit_fascia) refit(scene, *scene.implicit_fascia);
}

void coagulate_scene_implicit(ThoraxScene& scene, std::span<const std::uint8_t> coagulated,
                              Real factor) {
  for (std::optional<SceneImplicitMesh>* slot : {&scene.implicit_fascia, &scene.implicit_vessel}) {
    if (!*slot) continue;
    SceneImplicitMesh& f = **slot;
    const tissue::MeshObject& mesh = scene.patch.world.meshes[f.mesh];
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
}

physics::StepResult step_scene_implicit(ThoraxScene& scene, const physics::Executor& exec) {
  physics::StepResult result;
  if (!scene.implicit_fascia && !scene.implicit_vessel) return result;
  tissue::TissueWorld& w = scene.patch.world;
  // The fat's columns under both meshes, and the strands the instruments hold, as the step finds
  // them (it marks them again after).
  tissue::gather_fat_supports(w);
  tissue::mark_manipulated(w);
  for (std::optional<SceneImplicitMesh>* slot : {&scene.implicit_fascia, &scene.implicit_vessel}) {
    if (!*slot) continue;
    const physics::StepResult r = step_mesh(scene, **slot, exec);
    if (!r.ok() && result.ok()) result = r;
  }
  return result;
}

void release_scene_implicit(ThoraxScene& scene) {
  for (std::optional<SceneImplicitMesh>* slot : {&scene.implicit_vessel, &scene.implicit_fascia})
    if (*slot) release_mesh(scene, **slot);
}

}  // namespace imasim::scene
