#include "physics/validation.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace imasim::physics {

namespace {

bool finite_nonnegative(Real x) {
  return std::isfinite(x) && x >= 0;
}

// Checks one store; `stamp` starts at a value larger than any stamp used so far.
template <class Row>
std::string validate_store(const char* kind, const ColouredStore<Row>& store, const Model& model,
                           std::size_t particle_count, std::vector<std::uint32_t>& marks,
                           std::uint32_t& stamp) {
  const auto groups = store.groups();
  for (std::uint32_t g = 0; g < groups.size(); ++g) {
    ++stamp;
    const bool regular = g < ColouredStore<Row>::kColourCount;
    for (const Row& row : groups[g].rows) {
      if (row.material >= model.materials.size()) {
        return std::string(kind) + " constraint refers to missing material " +
               std::to_string(row.material);
      }
      for (std::uint32_t p : row.particles()) {
        if (p >= particle_count) {
          return std::string(kind) + " constraint refers to removed particle " + std::to_string(p);
        }
        if (!regular) continue;
        if (marks[p] == stamp) {
          return std::string(kind) + " colour " + std::to_string(g) + " holds particle " +
                 std::to_string(p) + " twice";
        }
        marks[p] = stamp;
        if ((store.particle_colour_mask(p) & (1u << g)) == 0) {
          return std::string(kind) + " colour mask of particle " + std::to_string(p) +
                 " misses colour " + std::to_string(g);
        }
      }
    }
  }
  return {};
}

}  // namespace

std::string validate_model(const Model& model) {
  const SolverParams& s = model.solver;
  if (!(std::isfinite(s.dt) && s.dt > 0)) return "solver.dt must be a positive number of seconds";
  if (s.substeps < 1) return "solver.substeps must be at least 1";
  if (s.iterations < 1) return "solver.iterations must be at least 1";
  if (s.coarse_stride < 1) return "solver.coarse_stride must be at least 1";
  if (s.bending_stride < 1) return "solver.bending_stride must be at least 1";
  if (s.stretch_sweeps < 1) return "solver.stretch_sweeps must be at least 1";
  if (s.coarse_sweeps < 1) return "solver.coarse_sweeps must be at least 1";
  if (!(std::isfinite(s.max_speed) && s.max_speed > 0)) return "solver.max_speed must be > 0";
  if (!(std::isfinite(s.push_out_speed) && s.push_out_speed > 0))
    return "solver.push_out_speed must be > 0";
  if (model.objects.empty()) return "model has no object";
  for (const ObjectParams& o : model.objects) {
    if (!o.gravity.allFinite()) return "object '" + o.name + "': gravity must be finite";
    if (!(o.linear_damping >= 0 && o.linear_damping < 1)) {
      return "object '" + o.name + "': linear_damping must be a share per 5 ms in [0, 1)";
    }
    if (!(o.angular_damping >= 0 && o.angular_damping <= 1)) {
      return "object '" + o.name + "': angular_damping must be a share per 5 ms in [0, 1]";
    }
  }
  for (std::size_t i = 0; i < model.materials.size(); ++i) {
    const ConstraintMaterial& m = model.materials[i];
    if (m.response == Response::xpbd && !finite_nonnegative(m.compliance)) {
      return "material " + std::to_string(i) + ": compliance must be >= 0";
    }
    if (m.response == Response::pbd && !(m.pbd_stiffness >= 0 && m.pbd_stiffness <= 1)) {
      return "material " + std::to_string(i) + ": PBD stiffness must be in [0, 1]";
    }
  }
  return {};
}

std::string validate_state(const Model& model, State& state) {
  const Particles& P = state.particles;
  const std::size_t n = P.size();
  if (P.predicted.size() != n || P.velocity.size() != n || P.rest_position.size() != n ||
      P.inverse_mass.size() != n || P.object.size() != n) {
    return "particle arrays differ in length";
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (P.object[i] >= model.objects.size()) {
      return "particle " + std::to_string(i) + " belongs to missing object";
    }
  }
  auto& marks = state.scratch.validation_stamp;
  if (marks.size() < n) return "state not prepared (call prepare_state)";
  std::fill(marks.begin(), marks.begin() + static_cast<std::ptrdiff_t>(n), 0u);
  std::uint32_t stamp = 0;
  const ConstraintSystem& cs = state.constraints;
  std::string error = validate_store("distance", cs.distance, model, n, marks, stamp);
  if (error.empty()) error = validate_store("dihedral", cs.dihedral, model, n, marks, stamp);
  if (error.empty()) error = validate_store("attachment", cs.attachment, model, n, marks, stamp);
  if (!error.empty()) return error;
  for (const ContactRow& c : state.contacts.rows) {
    if (c.particle >= state.particles.size()) return "a contact refers to a missing particle";
    if (c.body != kNoBody && c.body >= state.proxies.size()) {
      return "a contact refers to a missing proxy body";
    }
    if (!c.point0.allFinite() || !c.point1.allFinite() || !c.normal.allFinite()) {
      return "a contact's surface is not finite";
    }
  }
  for (const ProxyBody& b : state.proxies) {
    if (!b.offset.allFinite() || !b.rest.allFinite() || !std::isfinite(b.stiffness) ||
        !std::isfinite(b.damping) || !(b.max_offset >= 0)) {
      return "a proxy body is not finite";
    }
  }
  for (const BodyStopRow& r : state.body_stops) {
    if (r.body >= state.proxies.size()) return "a surface stop refers to a missing proxy body";
    if (!r.point0.allFinite() || !r.point1.allFinite() || !r.surface0.allFinite() ||
        !r.surface1.allFinite() || !r.normal.allFinite()) {
      return "a surface stop is not finite";
    }
  }
  for (const BodyAttachmentRow& r : state.body_attachments) {
    if (r.particle >= state.particles.size())
      return "a body's attachment refers to a missing particle";
    if (r.body >= state.proxies.size()) return "a body's attachment refers to a missing proxy body";
    if (!r.target.allFinite() || !(r.compliance >= 0)) return "a body's attachment is not finite";
  }
  for (const SupportRow& r : state.supports) {
    if (r.particle >= state.particles.size()) return "a support refers to a missing particle";
    if (!r.normal.allFinite() || !std::isfinite(r.offset) || !(r.compliance > 0) ||
        !std::isfinite(r.compliance))
      return "a support is not finite or has no stiffness";
  }
  for (const FollowRow& f : state.follows) {
    if (f.source >= state.particles.size() || f.destination >= state.particles.size()) {
      return "a coupling row refers to a missing particle";
    }
  }
  return {};
}

}  // namespace imasim::physics
