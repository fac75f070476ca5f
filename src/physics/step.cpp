#include "physics/step.hpp"

#include <algorithm>

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

// Predict (eq. 1). The stored velocity is PBD's step-mean velocity (x(t) - x(t-h)) / h, which
// under constant acceleration equals v(t) - a h / 2. Substituting v(t) in eq. 1 gives
//   x* = x + (v + a h) h,
// the symplectic-Euler prediction, exact in free fall for the mean velocity.
void predict(const Model& model, Particles& P, Real h, const Executor& exec) {
  exec.for_chunks(P.size(), kParticleBlock, [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) {
      if (P.inverse_mass[i] == 0) {
        P.velocity[i].setZero();
        P.predicted[i] = P.position[i];
        continue;
      }
      P.velocity[i] += h * model.objects[P.object[i]].gravity;
      P.predicted[i] = P.position[i] + h * P.velocity[i];
    }
  });
}

// Projects every colour group of a store, each in parallel over fixed chunks, then the overflow
// group serially. Within a chunk, Batch::size rows at a time go through Batch::project (SIMD,
// one row per lane) and the rest through project; chunks are multiples of the batch size, so a
// row's path does not depend on the thread count.
template <class Row, class Project, class BatchProject>
void project_store(ColouredStore<Row>& store, const ProjectionContext& ctx, const Executor& exec,
                   Project project, std::size_t batch, BatchProject project_batch) {
  auto groups = store.groups();
  for (std::uint32_t g = 0; g < ColouredStore<Row>::kColourCount; ++g) {
    auto& group = groups[g];
    const Row* rows = group.rows.data();
    Real* lambda = group.lambda.data();
    exec.for_chunks(group.rows.size(), kConstraintChunk, [&](std::size_t begin, std::size_t end) {
      std::size_t k = begin;
      for (; batch > 1 && k + batch <= end; k += batch)
        project_batch(rows + k, lambda + k, ctx);
      for (; k < end; ++k)
        project(rows[k], lambda[k], ctx);
    });
  }
  auto& overflow = groups[ColouredStore<Row>::kOverflow];  // serial, in insertion order
  for (std::size_t k = 0; k < overflow.rows.size(); ++k) {
    project(overflow.rows[k], overflow.lambda[k], ctx);
  }
}

constexpr auto kNoBatch = [](const auto*, Real*, const ProjectionContext&) {};
static_assert(kConstraintChunk % kDihedralBatch == 0);

// v = (p - x) / h, then x = p. Returns the first particle whose velocity is non-finite or
// faster than max_speed, or kInvalidIndex. Blocks are fixed, so the answer is thread-independent.
std::uint32_t update_velocities(State& state, Real h, Real max_speed, const Executor& exec) {
  Particles& P = state.particles;
  auto& first_bad = state.scratch.block_first_bad;
  const std::size_t blocks = (P.size() + kParticleBlock - 1) / kParticleBlock;
  const Real limit2 = max_speed * max_speed;
  exec.for_chunks(P.size(), kParticleBlock, [&](std::size_t begin, std::size_t end) {
    std::uint32_t bad = kInvalidIndex;
    for (std::size_t i = begin; i < end; ++i) {
      const Vec3 v = (P.predicted[i] - P.position[i]) / h;
      if (!(v.squaredNorm() <= limit2) && bad == kInvalidIndex) bad = static_cast<std::uint32_t>(i);
      P.velocity[i] = v;
      P.position[i] = P.predicted[i];
    }
    first_bad[begin / kParticleBlock] = bad;
  });
  for (std::size_t b = 0; b < blocks; ++b) {
    if (first_bad[b] != kInvalidIndex) return first_bad[b];
  }
  return kInvalidIndex;
}

}  // namespace

StepResult step(const Model& model, State& state, Executor& exec) {
  prepare_state(model, state);
  Particles& P = state.particles;
  StepScratch& scratch = state.scratch;
#if IMASIM_VALIDATION
  if (!validate_state(model, state).empty()) return {StepStatus::invalid_state, kInvalidIndex, 0};
#endif
  std::copy(P.position.begin(), P.position.end(), scratch.saved_position.begin());
  std::copy(P.velocity.begin(), P.velocity.end(), scratch.saved_velocity.begin());

  const SolverParams& solver = model.solver;
  const Real h = solver.dt / Real(solver.substeps);
  for (std::size_t m = 0; m < model.materials.size(); ++m) {
    scratch.projection_terms[m] = projection_terms(model.materials[m], h);
  }
  const ProjectionContext ctx{P.predicted.data(), P.inverse_mass.data(),
                              scratch.projection_terms.data()};

  StepResult result;
  exec.run([&] {
    for (std::uint32_t s = 0; s < solver.substeps; ++s) {
      predict(model, P, h, exec);
      ConstraintSystem& cs = state.constraints;
      cs.reset_lambda();
      for (std::uint32_t it = 0; it < solver.iterations; ++it) {
        // Lambdas (not function pointers) so that each projection inlines into its loop.
        project_store(
            cs.distance, ctx, exec,
            [](const DistanceRow& r, Real& l, const auto& c) { project_distance(r, l, c); }, 1,
            kNoBatch);
        project_store(
            cs.dihedral, ctx, exec,
            [](const DihedralRow& r, Real& l, const auto& c) { project_dihedral(r, l, c); },
            kDihedralBatch,
            [](const DihedralRow* r, Real* l, const auto& c) { project_dihedral_batch(r, l, c); });
        project_store(
            cs.attachment, ctx, exec,
            [](const AttachmentRow& r, Real& l, const auto& c) { project_attachment(r, l, c); }, 1,
            kNoBatch);
      }
      const std::uint32_t bad = update_velocities(state, h, solver.max_speed, exec);
      if (bad != kInvalidIndex) {
        const bool finite = P.velocity[bad].allFinite();
        result = {finite ? StepStatus::speed_limit : StepStatus::non_finite, bad, s};
        return;
      }
      apply_linear_damping(model, state, h, exec);
      apply_angular_damping(model, state, h);
    }
  });

  if (!result.ok()) {
    std::copy(scratch.saved_position.begin(), scratch.saved_position.begin() + P.size(),
              P.position.begin());
    std::copy(scratch.saved_velocity.begin(), scratch.saved_velocity.begin() + P.size(),
              P.velocity.begin());
    return result;
  }
  state.time += double(solver.dt);
  ++state.step_count;
  return result;
}

}  // namespace imasim::physics
