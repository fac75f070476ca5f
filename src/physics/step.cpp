#include "physics/step.hpp"

#include <algorithm>
#include <cstdint>
#include <span>

#include "math/stopwatch.hpp"
#include "math/validation_assert.hpp"
#include "physics/damping.hpp"
#include "physics/dihedral_batch.hpp"
#include "physics/validation.hpp"

namespace imasim::physics {

const char* to_string(StepStatus status) {
  switch (status) {
    case StepStatus::ok:
      return "ok";
    case StepStatus::non_finite:
      return "non_finite";
    case StepStatus::speed_limit:
      return "speed_limit";
    case StepStatus::invalid_state:
      return "invalid_state";
  }
  return "unknown";
}

namespace {

// Rows per chunk of a colour group (the unit of parallel work).
constexpr std::size_t kConstraintChunk = 512;

// Once per step: fixed (kinematic) particles take predicted = position and zero velocity (the
// substeps then need not visit them: projections never move them), and each object's range of
// dynamic particles is found, so the per-substep passes skip fixed runs such as the fascia's
// spare particles. With strided bending, fine particles take back their velocity offset
// (State::velocity_offset).
void begin_step(const Model& model, State& state) {
  Particles& P = state.particles;
  auto& ranges = state.scratch.object_ranges;
  const bool offsets = model.solver.effective_bending_stride() > 1;
  for (ObjectRange& r : ranges)
    r.dynamic_first = r.dynamic_end = 0;
  for (std::size_t i = 0; i < P.size(); ++i) {
    if (P.inverse_mass[i] == 0) {
      P.predicted[i] = P.position[i];
      P.velocity[i].setZero();
      state.velocity_offset[i].setZero();
      continue;
    }
    if (P.object[i] >= model.objects.size()) continue;  // validate_state reports it
    if (offsets && !model.objects[P.object[i]].coarse) P.velocity[i] += state.velocity_offset[i];
    ObjectRange& r = ranges[P.object[i]];
    if (r.dynamic_end == 0) r.dynamic_first = static_cast<std::uint32_t>(i);
    r.dynamic_end = static_cast<std::uint32_t>(i + 1);
  }
}

// Calls f(i) for every dynamic particle of the fine (not coarse) objects, in order.
template <class F>
void for_fine_particles(const Model& model, const State& state, const F& f) {
  const Particles& P = state.particles;
  for (std::size_t o = 0; o < model.objects.size(); ++o) {
    if (model.objects[o].coarse) continue;
    const ObjectRange& r = state.scratch.object_ranges[o];
    for (std::uint32_t i = r.dynamic_first; i < r.dynamic_end; ++i) {
      if (P.object[i] == o && P.inverse_mass[i] != 0) f(i);
    }
  }
}

// The objects a pass steps (the fine ones, the coarse ones in their substep), and the substep
// length each takes.
struct SubstepPlan {
  bool fine_active = true, coarse_active = false;
  Real fine_h = 0, coarse_h = 0;
  bool active(const ObjectParams& o) const { return o.coarse ? coarse_active : fine_active; }
  Real h(const ObjectParams& o) const { return o.coarse ? coarse_h : fine_h; }
};

// Calls body(begin, end, object, chunk) over fixed chunks of every active object's dynamic range,
// in object order, with the chunk's number across every object's (for per-chunk results: the
// fine and the coarse band's passes, run side by side, number theirs apart).
template <class Body>
void for_active_particles(const Model& model, const State& state, const SubstepPlan& plan,
                          const Executor& exec, const Body& body) {
  const auto& ranges = state.scratch.object_ranges;
  std::size_t chunk_base = 0;
  for (std::size_t o = 0; o < model.objects.size(); ++o) {
    const ObjectRange& r = ranges[o];
    if (r.dynamic_end == 0) continue;
    const std::size_t first = r.dynamic_first, n = r.dynamic_end - r.dynamic_first;
    const std::size_t base = chunk_base;
    chunk_base += (n + kParticleBlock - 1) / kParticleBlock;
    if (!plan.active(model.objects[o])) continue;
    const auto object = static_cast<ObjectId>(o);
    exec.for_chunks(n, kParticleBlock, [&](std::size_t begin, std::size_t end) {
      body(first + begin, first + end, object, base + begin / kParticleBlock);
    });
  }
}

// Predict (eq. 1). The stored velocity is PBD's step-mean velocity (x(t) - x(t-h)) / h, which
// under constant acceleration equals v(t) - a h / 2. Substituting v(t) in eq. 1 gives
//   x* = x + (v + a h) h,
// the symplectic-Euler prediction, exact in free fall for the mean velocity.
void predict(const Model& model, State& state, const SubstepPlan& plan, const Executor& exec) {
  Particles& P = state.particles;
  for_active_particles(model, state, plan, exec,
                       [&](std::size_t begin, std::size_t end, ObjectId o, std::size_t) {
                         const ObjectParams& object = model.objects[o];
                         const Real h = plan.h(object);
                         const Vec3 dv = h * object.gravity;
                         // Raw pointers: a store through one vector could otherwise alias the
                         // others' data pointers, reloaded every particle.
                         const Real* w = P.inverse_mass.data();
                         const ObjectId* owner = P.object.data();
                         const Vec3* x = P.position.data();
                         Vec3* v = P.velocity.data();
                         Vec3* p = P.predicted.data();
                         for (std::size_t i = begin; i < end; ++i) {
                           if (w[i] == 0 || owner[i] != o) continue;
                           v[i] += dv;
                           p[i] = x[i] + h * v[i];
                         }
                       });
}

// Projects the colour groups of one band of a store, each in parallel over fixed chunks, then
// the band's overflow group serially. Within a chunk, `batch` rows at a time go through
// project_batch (SIMD, one row per lane) and the rest through project; chunks are multiples of
// the batch size, so a row's path does not depend on the thread count.
template <class Row, class Project, class BatchProject>
void project_store(ColouredStore<Row>& store, std::uint32_t band, const ProjectionContext& ctx,
                   const Executor& exec, Project project, std::size_t batch,
                   BatchProject project_batch) {
  using Store = ColouredStore<Row>;
  auto groups = store.groups();
  for (std::uint32_t g = store.band_first(band); g < store.band_end(band); ++g) {
    auto& group = groups[g];
    const Row* rows = group.rows.data();
    auto* lambda = group.lambda.data();
    exec.for_chunks(group.rows.size(), kConstraintChunk, [&](std::size_t begin, std::size_t end) {
      std::size_t k = begin;
      for (; batch > 1 && k + batch <= end; k += batch)
        project_batch(rows + k, lambda + k, ctx);
      for (; k < end; ++k)
        project(rows[k], lambda[k], ctx);
    });
  }
  auto& overflow = groups[Store::overflow_group(band)];  // serial, in insertion order
  for (std::size_t k = 0; k < overflow.rows.size(); ++k) {
    project(overflow.rows[k], overflow.lambda[k], ctx);
  }
}

// A further sweep of the coarse band: its rows near what acts on it from outside
// (active_rows.hpp), in projection order, serially.
void project_active_rows(ConstraintSystem& cs, const ActiveRows& active,
                         const ProjectionContext& ctx) {
  auto distance = cs.distance.groups();
  for (std::size_t k = 0; k < active.distance_count; ++k) {
    const RowRef r = active.distance[k];
    project_distance(distance[r.group].rows[r.position], distance[r.group].lambda[r.position], ctx);
  }
  auto attachment = cs.attachment.groups();
  for (std::size_t k = 0; k < active.attachment_count; ++k) {
    const RowRef r = active.attachment[k];
    project_attachment(attachment[r.group].rows[r.position], attachment[r.group].lambda[r.position],
                       ctx);
  }
}

constexpr auto kNoBatch = [](const auto*, auto*, const ProjectionContext&) {};
static_assert(kConstraintChunk % kDihedralBatch == 0);

// One sweep over a band's rows. `bending`: the context of its dihedral rows, or null in a
// substep that does not project them (SolverParams::bending_stride).
void project_band(ConstraintSystem& cs, std::uint32_t band, const ProjectionContext& ctx,
                  const ProjectionContext* bending, const Executor& exec) {
  // Lambdas (not function pointers) so that each projection inlines into its loop.
  project_store(
      cs.distance, band, ctx, exec,
      [](const DistanceRow& r, Real& l, const auto& c) { project_distance(r, l, c); }, 1, kNoBatch);
  if (bending != nullptr) {
    project_store(
        cs.dihedral, band, *bending, exec,
        [](const DihedralRow& r, Real& l, const auto& c) { project_dihedral(r, l, c); },
        kDihedralBatch,
        [](const DihedralRow* r, Real* l, const auto& c) { project_dihedral_batch(r, l, c); });
  }
  project_store(
      cs.attachment, band, ctx, exec,
      [](const AttachmentRow& r, Vec3& l, const auto& c) { project_attachment(r, l, c); }, 1,
      kNoBatch);
}

// Once per step: the contact and follow rows are reordered band 0 first (std::partition: the
// same input gives the same order, so runs stay deterministic), so that each substep's passes
// visit their band's rows only. A row's band is its particle's object's (a follow row's, its
// destination's).
void order_rows_by_band(const Model& model, State& state) {
  const Particles& P = state.particles;
  auto fine = [&](std::uint32_t i) {
    IMASIM_ASSERT(i < P.size());
    return P.object[i] >= model.objects.size() || !model.objects[P.object[i]].coarse;
  };
  auto& contacts = state.contacts.rows;
  state.scratch.contact_split = static_cast<std::size_t>(
      std::partition(contacts.begin(), contacts.end(),
                     [&](const ContactRow& c) { return fine(c.particle); }) -
      contacts.begin());
  auto& supports = state.supports;
  state.scratch.support_split = static_cast<std::size_t>(
      std::partition(supports.begin(), supports.end(),
                     [&](const SupportRow& r) { return fine(r.particle); }) -
      supports.begin());
  auto& held = state.body_attachments;
  state.scratch.body_attachment_split = static_cast<std::size_t>(
      std::partition(held.begin(), held.end(),
                     [&](const BodyAttachmentRow& r) { return fine(r.particle); }) -
      held.begin());
  auto& follows = state.follows;
  state.scratch.follow_split = static_cast<std::size_t>(
      std::partition(follows.begin(), follows.end(),
                     [&](const FollowRow& f) { return fine(f.destination); }) -
      follows.begin());
  auto& crosses = state.scratch.follow_crosses;
  crosses.resize(follows.size());  // grows only with the rows (no allocation at a steady count)
  state.scratch.follow_sources.resize(follows.size());
  for (std::size_t k = 0; k < follows.size(); ++k)
    crosses[k] = fine(follows[k].source) != fine(follows[k].destination);
}

// The rows of `band` in a sequence ordered by order_rows_by_band.
template <class Row>
std::span<Row> band_rows(std::vector<Row>& rows, std::size_t split, std::uint32_t band) {
  return band == 0 ? std::span<Row>(rows.data(), split)
                   : std::span<Row>(rows.data() + split, rows.size() - split);
}

// The contacts of one band, in order, then the particles proxy bodies hold (body_attachment.hpp).
// Positions hold the substep's start until
// update_velocities, so they are the friction's reference.
// A row naming a proxy body shares its corrections with it (contact.hpp), against the body's
// offset at the band's substep start.
// pushed: how far a starting overlap may have been pushed out by the substep's end (unit: m).
// proxies: the band's view of the proxy bodies (the coarse band's, a copy: below).
void project_contacts(State& state, std::span<ProxyBody> proxies, std::uint32_t band, Real tau0,
                      Real tau1, Real h, Real pushed) {
  Particles& P = state.particles;
  // The columns under the tissue first: a contact, hard, has the last word.
  for (SupportRow& r : band_rows(state.supports, state.scratch.support_split, band)) {
    IMASIM_ASSERT(r.particle < P.size());
    project_support(r, P.predicted.data(), P.inverse_mass.data(), h);
  }
  for (ContactRow& c : band_rows(state.contacts.rows, state.scratch.contact_split, band)) {
    const Real allowance = overlap_allowance(c, pushed);
    if (c.body == kNoBody) {
      project_contact(c, P.predicted.data(), P.position.data(), P.inverse_mass.data(), tau0, tau1,
                      h, allowance);
      continue;
    }
    IMASIM_ASSERT(c.body < proxies.size());
    ProxyBody& b = proxies[c.body];
    project_contact(c, P.predicted.data(), P.position.data(), P.inverse_mass.data(), b,
                    band == 0 ? b.substep_start : b.coarse_start, tau0, tau1, h, allowance);
  }
  // The particles the bodies hold, after their contacts: one body, so serially, in order.
  for (BodyAttachmentRow& r :
       band_rows(state.body_attachments, state.scratch.body_attachment_split, band)) {
    IMASIM_ASSERT(r.particle < P.size() && r.body < proxies.size());
    project_body_attachment(r, P.predicted.data(), P.inverse_mass.data(), proxies[r.body], h);
  }
}

// Each row's overlap at the step's start: its particle against the plane where it began (a
// body's offset has not moved yet).
void measure_start_depths(State& state) {
  const Vec3* x = state.particles.position.data();
  for (ContactRow& c : state.contacts.rows) {
    const Real gap = c.normal.dot(x[c.particle] - c.point0) - c.margin;
    c.start_depth = gap < 0 ? -gap : Real(0);
  }
}

// The proxies' couplings to their devices, after each iteration's contacts (fine substep h),
// then the surfaces that stop them (the heart, the chest wall): those have the last word, so
// the coupling's pull and its bound never leave a proxy inside them.
void project_proxy_couplings(State& state, Real h, Real tau0, Real tau1) {
  for (ProxyBody& b : state.proxies)
    project_proxy_coupling(b, h);
  for (BodyStopRow& r : state.body_stops) {
    IMASIM_ASSERT(r.body < state.proxies.size());
    ProxyBody& b = state.proxies[r.body];
    project_body_stop(r, b, b.substep_start, tau0, tau1);
  }
}

// The follow rows whose destination is in `band`, in order. A row whose source is in the other
// band reads it as the group of substeps began (StepScratch::follow_sources): the bands run side
// by side and never read each other's particles while they do.
void project_follows(State& state, std::uint32_t band) {
  Particles& P = state.particles;
  const std::size_t first = band == 0 ? 0 : state.scratch.follow_split;
  const auto rows = band_rows(state.follows, state.scratch.follow_split, band);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const FollowRow& f = rows[k];
    IMASIM_ASSERT(f.source < P.size() && f.destination < P.size());
    if (P.inverse_mass[f.destination] == 0) continue;
    if (state.scratch.follow_crosses[first + k])
      project_follow(f, state.scratch.follow_sources[first + k], P.predicted.data());
    else
      project_follow(f, P.predicted[f.source], P.predicted.data());
  }
}

// At the start of a group of substeps: the sources the crossing follow rows read, their positions
// (where the last substep left them, or the caller between steps).
void snapshot_crossing_sources(State& state) {
  const Vec3* p = state.particles.position.data();
  for (std::size_t k = 0; k < state.follows.size(); ++k)
    if (state.scratch.follow_crosses[k])
      state.scratch.follow_sources[k] = p[state.follows[k].source];
}

// h: the band's substep; a body's surface moved with its offset over it as well (proxies: the
// band's view of the bodies).
void remove_separating_velocities(State& state, std::span<const ProxyBody> proxies,
                                  std::uint32_t band, Real inverse_dt, Real h) {
  Vec3* v = state.particles.velocity.data();
  for (const ContactRow& c : band_rows(state.contacts.rows, state.scratch.contact_split, band)) {
    if (c.body == kNoBody) {
      remove_separating_velocity(c, v, inverse_dt);
      continue;
    }
    const ProxyBody& b = proxies[c.body];
    const Vec3& start = band == 0 ? b.substep_start : b.coarse_start;
    remove_separating_velocity(c, v, inverse_dt, (b.offset - start) / h);
  }
}

void reset_contact_depths(State& state, std::uint32_t band) {
  for (ContactRow& c : band_rows(state.contacts.rows, state.scratch.contact_split, band)) {
    c.depth = 0;
    c.substep_normal = 0;
    c.substep_friction = Vec3::Zero();
  }
  for (BodyAttachmentRow& r :
       band_rows(state.body_attachments, state.scratch.body_attachment_split, band))
    r.lambda = Vec3::Zero();
  for (SupportRow& r : band_rows(state.supports, state.scratch.support_split, band))
    r.lambda = 0;
  if (band != 0) return;
  for (BodyStopRow& r : state.body_stops) {  // the bodies move in the fine substeps
    r.depth = 0;
    r.substep_normal = 0;
    r.substep_friction = Vec3::Zero();
  }
}

// v = (p - x) / h, then x = p, and linear damping (eq. 4): v <- keep v with the object's factor
// for its substep. Returns the first particle whose velocity is non-finite, or kInvalidIndex.
// Chunks are fixed, so the answer is thread-independent.
std::uint32_t update_velocities(const Model& model, State& state, const SubstepPlan& plan,
                                const Executor& exec) {
  Particles& P = state.particles;
  auto& first_bad = state.scratch.block_first_bad;
  for_active_particles(model, state, plan, exec,
                       [&](std::size_t begin, std::size_t end, ObjectId o, std::size_t c) {
                         const ObjectParams& object = model.objects[o];
                         const Real inverse_h = 1 / plan.h(object);
                         const Real keep = state.scratch.object_keep[o];
                         std::uint32_t bad = kInvalidIndex;
                         const Real* w = P.inverse_mass.data();  // raw pointers: see predict()
                         const ObjectId* owner = P.object.data();
                         const Vec3* p = P.predicted.data();
                         Vec3* x = P.position.data();
                         Vec3* velocity = P.velocity.data();
                         for (std::size_t i = begin; i < end; ++i) {
                           if (w[i] == 0 || owner[i] != o) continue;
                           const Vec3 v = (p[i] - x[i]) * inverse_h;
                           if (!v.allFinite() && bad == kInvalidIndex)
                             bad = static_cast<std::uint32_t>(i);
                           velocity[i] = keep * v;
                           x[i] = p[i];
                         }
                         first_bad[c] = bad;
                       });
  std::uint32_t first = kInvalidIndex;
  std::size_t chunk_base = 0;
  for (std::size_t o = 0; o < model.objects.size(); ++o) {
    const ObjectRange& r = state.scratch.object_ranges[o];
    if (r.dynamic_end == 0) continue;
    const std::size_t chunks =
        (r.dynamic_end - r.dynamic_first + kParticleBlock - 1) / kParticleBlock;
    if (plan.active(model.objects[o]))
      for (std::size_t c = chunk_base; c < chunk_base + chunks; ++c)
        first = std::min(first, first_bad[c]);
    chunk_base += chunks;
  }
  return first;
}

}  // namespace

StepResult step(const Model& model, State& state, Executor& exec) {
  Stopwatch clock;
  StepProfile profile;
  prepare_state(model, state);
  Particles& P = state.particles;
  StepScratch& scratch = state.scratch;
#if IMASIM_VALIDATION
  if (!validate_state(model, state).empty()) {
    StepResult invalid;
    invalid.status = StepStatus::invalid_state;
    return invalid;
  }
#endif
  std::copy(P.position.begin(), P.position.end(), scratch.saved_position.begin());
  std::copy(P.velocity.begin(), P.velocity.end(), scratch.saved_velocity.begin());

  const SolverParams& solver = model.solver;
  const std::uint32_t stride = solver.effective_coarse_stride();
  const std::uint32_t bending_stride = solver.effective_bending_stride();
  SubstepPlan plan;
  plan.fine_h = solver.dt / Real(solver.substeps);
  plan.coarse_h = plan.fine_h * Real(stride);
  for (std::size_t m = 0; m < model.materials.size(); ++m) {
    scratch.projection_terms[m] = projection_terms(model.materials[m], plan.fine_h);
    scratch.coarse_terms[m] = projection_terms(model.materials[m], plan.coarse_h);
    scratch.bending_terms[m] =
        strided_projection_terms(model.materials[m], plan.fine_h, bending_stride);
  }
  for (std::size_t o = 0; o < model.objects.size(); ++o) {
    const ObjectParams& object = model.objects[o];
    scratch.object_keep[o] = damping_keep(object.linear_damping, plan.h(object));
  }
  begin_step(model, state);
  order_rows_by_band(model, state);
  if (solver.coarse_sweeps > 1) find_active_rows(state, 1, scratch.coarse_active);
  for (ContactRow& c : state.contacts.rows)
    c.normal_impulse = 0;
  for (BodyStopRow& r : state.body_stops) {
    r.normal_impulse = 0;
    r.friction_impulse = Vec3::Zero();
  }
  for (BodyAttachmentRow& r : state.body_attachments)
    r.impulse = Vec3::Zero();
  for (SupportRow& r : state.supports)
    r.impulse = 0;
  measure_start_depths(state);
  for (ProxyBody& b : state.proxies) {
    keep_proxy_finite(b);
    b.step_start = b.coarse_start = b.offset;
    b.impulse = Vec3::Zero();
  }
  scratch.group_proxies.resize(state.proxies.size());  // grow only with the instruments
  scratch.coarse_proxies.resize(state.proxies.size());
  const ProjectionContext fine{P.predicted.data(), P.inverse_mass.data(),
                               scratch.projection_terms.data()};
  const ProjectionContext coarse{P.predicted.data(), P.inverse_mass.data(),
                                 scratch.coarse_terms.data()};
  const ProjectionContext fine_bending{P.predicted.data(), P.inverse_mass.data(),
                                       scratch.bending_terms.data()};

  profile[Stage::predict] += clock.lap();

  StepResult result;
  ConstraintSystem& cs = state.constraints;
  const Real inverse_dt = 1 / solver.dt;
  SubstepPlan fine_plan = plan, coarse_plan = plan;
  fine_plan.coarse_active = false;
  coarse_plan.fine_active = false;
  coarse_plan.coarse_active = true;
  const bool two_bands = std::any_of(model.objects.begin(), model.objects.end(),
                                     [&](const ObjectParams& o) { return o.coarse; });
  // A fine substep's taus and its first and last part. The first ends where a coarse substep
  // joins the fine band (after its first sweep's contacts); the last is everything after.
  struct FineTimes {
    Real tau0, tau1, pushed;
    bool bending;
  };
  auto fine_times = [&](std::uint32_t s) {
    return FineTimes{Real(s) / Real(solver.substeps), Real(s + 1) / Real(solver.substeps),
                     solver.push_out_speed * (Real(s + 1) / Real(solver.substeps)) * solver.dt,
                     (s + 1) % bending_stride == 0};
  };
  auto fine_sweep = [&](const FineTimes& t, bool with_bending) {
    project_band(cs, 0, fine, with_bending && t.bending ? &fine_bending : nullptr, exec);
    project_follows(state, 0);
    profile[Stage::solve] += clock.lap();
    project_contacts(state, state.proxies, 0, t.tau0, t.tau1, plan.fine_h, t.pushed);
    profile[Stage::contacts] += clock.lap();
  };
  auto fine_begin = [&](std::uint32_t s) {
    if (bending_stride > 1 && s == solver.substeps - bending_stride) {
      for_fine_particles(model, state,
                         [&](std::uint32_t i) { scratch.group_start[i] = P.position[i]; });
    }
    predict(model, state, fine_plan, exec);
    profile[Stage::predict] += clock.lap();
    cs.reset_lambda(0);
    for (ProxyBody& b : state.proxies) {
      b.substep_start = b.offset;
      b.lambda = Vec3::Zero();
    }
    reset_contact_depths(state, 0);
    profile[Stage::solve] += clock.lap();
    fine_sweep(fine_times(s), true);
  };
  // false: a velocity was not finite (result says which).
  auto fine_finish = [&](std::uint32_t s) {
    const FineTimes t = fine_times(s);
    for (std::uint32_t it = 0; it < solver.iterations; ++it) {
      if (it > 0) fine_sweep(t, true);
      project_proxy_couplings(state, plan.fine_h, t.tau0, t.tau1);
      // Further sweeps of the fine band's stiff rows, their lambdas accumulating: stretch,
      // attachments and what they act against (contacts, the proxies' coupling), not bending.
      for (std::uint32_t sweep = 1; sweep < solver.stretch_sweeps; ++sweep) {
        fine_sweep(t, false);
        project_proxy_couplings(state, plan.fine_h, t.tau0, t.tau1);
      }
    }
    const std::uint32_t bad = update_velocities(model, state, fine_plan, exec);
    if (bad != kInvalidIndex) {
      result.status = StepStatus::non_finite;
      result.particle = bad;
      result.substep = s;
      return false;
    }
    remove_separating_velocities(state, state.proxies, 0, inverse_dt, plan.fine_h);
    // Angular damping (eq. 4's k_c) at the coarse rate, over the coarse substep's length: the share
    // it removes per 5 ms is the same, and it is most of a fine substep's particle passes.
    if ((s + 1) % stride == 0) {
      for (std::size_t o = 0; o < model.objects.size(); ++o)
        if (fine_plan.active(model.objects[o]))
          apply_angular_damping(model, state, o, plan.coarse_h);
    }
    profile[Stage::velocities] += clock.lap();
    return true;
  };
  // The coarse band's substep, ending with fine substep s: its rows against the proxies as the
  // group began (their copy, coarse_proxies). Reads no fine particle and writes none, so it runs
  // beside the fine band. Returns the first particle whose velocity is not finite, if any.
  auto coarse_substep = [&](std::uint32_t s) {
    const Real tau1 = Real(s + 1) / Real(solver.substeps);
    const Real tau0 = Real(s + 1 - stride) / Real(solver.substeps);
    const Real pushed = solver.push_out_speed * tau1 * solver.dt;
    predict(model, state, coarse_plan, exec);
    cs.reset_lambda(1);
    reset_contact_depths(state, 1);
    for (std::uint32_t it = 0; it < solver.iterations; ++it) {
      // coarse_sweeps sweeps, lambdas accumulating, its bending once: its substep is
      // coarse_stride times the fine one, and so is its softness squared.
      for (std::uint32_t sweep = 0; sweep < solver.coarse_sweeps; ++sweep) {
        if (sweep == 0)
          project_band(cs, 1, coarse, &coarse, exec);
        else
          project_active_rows(cs, scratch.coarse_active, coarse);
        project_follows(state, 1);
        project_contacts(state, scratch.coarse_proxies, 1, tau0, tau1, plan.coarse_h, pushed);
      }
    }
    const std::uint32_t bad = update_velocities(model, state, coarse_plan, exec);
    if (bad != kInvalidIndex) return bad;
    remove_separating_velocities(state, scratch.coarse_proxies, 1, inverse_dt, plan.coarse_h);
    for (std::size_t o = 0; o < model.objects.size(); ++o)
      if (model.objects[o].coarse) apply_angular_damping(model, state, o, plan.coarse_h);
    return kInvalidIndex;
  };

  exec.run([&] {
    // Groups of substeps: the fine ones up to and with the next coarse substep's last (the last
    // group may have no coarse substep).
    for (std::uint32_t first = 0; first < solver.substeps;) {
      std::uint32_t last = first;
      while (last + 1 < solver.substeps && (last + 1) % stride != 0)
        ++last;
      const bool coarse_here = two_bands && (last + 1) % stride == 0;
      snapshot_crossing_sources(state);
      if (!coarse_here) {
        for (std::uint32_t s = first; s <= last; ++s) {
          fine_begin(s);
          if (!fine_finish(s)) return;
        }
        first = last + 1;
        continue;
      }
      std::copy(state.proxies.begin(), state.proxies.end(), scratch.group_proxies.begin());
      std::copy(state.proxies.begin(), state.proxies.end(), scratch.coarse_proxies.begin());
      bool fine_ok = true;
      std::uint32_t coarse_bad = kInvalidIndex;
      exec.run_side_by_side(
          [&] {
            for (std::uint32_t s = first; s < last && fine_ok; ++s) {
              fine_begin(s);
              fine_ok = fine_finish(s);
            }
            if (fine_ok) fine_begin(last);
          },
          [&] { coarse_bad = coarse_substep(last); });
      profile[Stage::solve] += clock.lap();
      if (!fine_ok) return;
      if (coarse_bad != kInvalidIndex) {
        result.status = StepStatus::non_finite;
        result.particle = coarse_bad;
        result.substep = last;
        return;
      }
      // The bands join: the proxies take what the coarse band's contacts moved them by.
      for (std::size_t b = 0; b < state.proxies.size(); ++b) {
        ProxyBody& proxy = state.proxies[b];
        proxy.offset += scratch.coarse_proxies[b].offset - scratch.group_proxies[b].offset;
        proxy.impulse += scratch.coarse_proxies[b].impulse - scratch.group_proxies[b].impulse;
      }
      if (!fine_finish(last)) return;
      for (ProxyBody& b : state.proxies)
        b.coarse_start = b.offset;
      first = last + 1;
    }
  });

  // The speed guard on the step's mean velocity: a substep's velocity can legitimately spike
  // (a grasp pinching tissue onto the jaws moves it millimetres in one substep).
  if (result.ok()) {
    const Real limit = solver.max_speed * solver.dt;
    for (std::size_t i = 0; i < P.size(); ++i) {
      if ((P.position[i] - scratch.saved_position[i]).squaredNorm() > limit * limit) {
        result.status = StepStatus::speed_limit;
        result.particle = static_cast<std::uint32_t>(i);
        result.substep = solver.substeps - 1;
        break;
      }
    }
  }
  // Strided bending: the stored velocity of a fine particle is its mean over the last bending
  // group; the solver's remains as the offset (State::velocity_offset).
  if (result.ok() && bending_stride > 1) {
    const Real inverse_span = 1 / (plan.fine_h * Real(bending_stride));
    for_fine_particles(model, state, [&](std::uint32_t i) {
      const Vec3 mean = (P.position[i] - scratch.group_start[i]) * inverse_span;
      state.velocity_offset[i] = P.velocity[i] - mean;
      P.velocity[i] = mean;
    });
  }
  profile[Stage::velocities] += clock.lap();
  result.profile = profile;
  if (!result.ok()) {
    std::copy(scratch.saved_position.begin(), scratch.saved_position.begin() + P.size(),
              P.position.begin());
    std::copy(scratch.saved_velocity.begin(), scratch.saved_velocity.begin() + P.size(),
              P.velocity.begin());
    for (ProxyBody& b : state.proxies)
      b.offset = b.step_start;
    return result;
  }
  state.time += double(solver.dt);
  ++state.step_count;
  return result;
}

}  // namespace imasim::physics
