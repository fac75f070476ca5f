#include "physics/implicit_membrane.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "physics/dihedral_constraint.hpp"

namespace imasim::physics {

namespace {

std::string edge_name(std::size_t e) {
  return "implicit membrane: edge " + std::to_string(e);
}

// The Hessian of one edge's energy with respect to its first end (unit: N/m): the regime's
// stiffness along the edge, the tension over the length across it. In compression that is
// negative: exact, it keeps Newton quadratic where a slack membrane's bending and mass hold the
// matrix positive definite; clamped to zero, the matrix is positive definite always but Newton
// only linear (the fascia draped on the heart, a fifth of its edges slack: 9 iterations a step
// against 3).
Mat3 edge_stiffness(const StiffeningSpring& s, const Vec3& d, bool exact) {
  const Real l = d.norm();
  if (!(l > Real(1e-12))) return Mat3::Zero();
  const Vec3 n = d / l;
  const Mat3 along = n * n.transpose();
  const Real t = tension(s, l);
  const Real across = (exact ? t : std::max(Real(0), t)) / l;
  return stiffness_at(s, l) * along + across * (Mat3::Identity() - along);
}

// Free rows a thread takes at a time in the gradient's gather.
constexpr std::size_t kRowChunk = 256;

}  // namespace

FrictionTerms friction_potential(Real mu_lambda, Real slip, Real stick_slip) {
  const Real eps = stick_slip;
  if (slip >= eps)  // sliding: Coulomb's bound, mu lambda against the slip
    return {mu_lambda * slip, mu_lambda / slip, 0};
  // Sticking: f0 = -s^3 / (3 eps^2) + s^2 / eps + eps / 3, f0' = 2 s / eps - s^2 / eps^2,
  // f0'' = 2 / eps - 2 s / eps^2; f0'(s) / s = 2 / eps - s / eps^2 stays finite at s = 0.
  const Real s = slip, inverse = 1 / eps;
  return {mu_lambda * (s * s * inverse * (1 - s * inverse / 3) + eps / 3),
          mu_lambda * inverse * (2 - s * inverse), mu_lambda * 2 * inverse * (1 - s * inverse)};
}

ImplicitMembrane::ImplicitMembrane(std::vector<Real> mass, const std::vector<std::uint8_t>& fixed,
                                   std::vector<MembraneEdge> edges, Real h,
                                   std::vector<MembraneHinge> hinges, std::uint32_t bodies,
                                   std::vector<MembraneDihedral> dihedrals)
    : mass_(std::move(mass)),
      edges_(std::move(edges)),
      h_(h),
      hinges_(std::move(hinges)),
      body_count_(bodies),
      dihedrals_(std::move(dihedrals)) {
  const std::size_t n = mass_.size();
  if (fixed.size() != n)
    throw std::invalid_argument("implicit membrane: " + std::to_string(fixed.size()) +
                                " fixed flags for " + std::to_string(n) + " vertices");
  if (!(h_ > 0)) throw std::invalid_argument("implicit membrane: step h must be positive");
  free_index_.assign(n, kFixed);
  for (std::size_t v = 0; v < n; ++v) {
    if (fixed[v]) continue;
    if (!(mass_[v] > 0))
      throw std::invalid_argument("implicit membrane: free vertex " + std::to_string(v) +
                                  " has no mass");
    free_index_[v] = static_cast<std::uint32_t>(free_vertices_.size());
    free_vertices_.push_back(static_cast<std::uint32_t>(v));
  }
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const MembraneEdge& edge = edges_[e];
    const StiffeningSpring& s = edge.spring;
    if (edge.i >= n || edge.j >= n || edge.i == edge.j)
      throw std::invalid_argument(edge_name(e) + " names vertices out of range or twice");
    if (!(s.rest_length > 0) || !(s.toe_stiffness > 0) ||
        !(s.linear_stiffness >= s.toe_stiffness) || !(s.toe_strain > 0))
      throw std::invalid_argument(edge_name(e) +
                                  ": rest length and toe stiffness must be positive, the linear "
                                  "stiffness at least the toe's, the toe strain positive");
  }

  for (std::size_t k = 0; k < hinges_.size(); ++k) {
    for (std::uint32_t v : hinges_[k].v)
      if (v >= n)
        throw std::invalid_argument("implicit membrane: hinge " + std::to_string(k) +
                                    " names a vertex out of range");
    if (!(hinges_[k].stiffness >= 0))
      throw std::invalid_argument("implicit membrane: hinge " + std::to_string(k) +
                                  ": stiffness must not be negative");
  }

  for (std::size_t k = 0; k < dihedrals_.size(); ++k) {
    const MembraneDihedral& d = dihedrals_[k];
    const std::string name = "implicit membrane: dihedral " + std::to_string(k);
    for (std::uint32_t p = 0; p < 4; ++p) {
      if (d.v[p] >= n) throw std::invalid_argument(name + " names a vertex out of range");
      for (std::uint32_t q = p + 1; q < 4; ++q)
        if (d.v[p] == d.v[q]) throw std::invalid_argument(name + " names a vertex twice");
    }
    if (!(d.stiffness >= 0) || !std::isfinite(d.rest_angle))
      throw std::invalid_argument(name + ": stiffness must not be negative, the rest angle finite");
    dihedral_rest_.push_back({std::cos(d.rest_angle), std::sin(d.rest_angle)});
  }

  // The pattern: a block on every free row's diagonal, between the free ends of every edge and
  // between every two free vertices of a hinge, cut or not, so that it never changes; a body's
  // row joins every free vertex.
  const auto free_rows = static_cast<std::uint32_t>(free_vertices_.size());
  block_rows_ = free_rows + body_count_;
  std::vector<BlockCholesky::Pair> pairs;
  auto join = [&](std::uint32_t a, std::uint32_t b) {
    if (a != kFixed && b != kFixed && a != b) pairs.emplace_back(std::min(a, b), std::max(a, b));
  };
  for (const MembraneEdge& edge : edges_)
    join(free_index_[edge.i], free_index_[edge.j]);
  for (const MembraneHinge& hinge : hinges_)
    for (std::uint32_t p = 0; p < 4; ++p)
      for (std::uint32_t q = p + 1; q < 4; ++q)
        join(free_index_[hinge.v[p]], free_index_[hinge.v[q]]);
  for (const MembraneDihedral& d : dihedrals_)
    for (std::uint32_t p = 0; p < 4; ++p)
      for (std::uint32_t q = p + 1; q < 4; ++q)
        join(free_index_[d.v[p]], free_index_[d.v[q]]);
  for (std::uint32_t b = 0; b < body_count_; ++b)
    for (std::uint32_t a = 0; a < free_rows; ++a)
      join(a, free_rows + b);
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  cholesky_.analyse(block_rows_, pairs);
  pairs_ = pairs;
  held_.assign(free_rows, kNone);
  pending_.assign(free_rows, kNone);
  released_.assign(free_rows, 0);
  factored_held_.assign(free_rows, 0);
  hessian_.assign(block_rows_ + pairs.size(), Mat3::Zero());
  constant_hessian_.assign(hessian_.size(), Mat3::Zero());
  auto block = [&](std::uint32_t a, std::uint32_t b) -> Block {
    if (a == kFixed || b == kFixed) return kFixed;
    if (a == b) return a;
    const BlockCholesky::Pair key(std::min(a, b), std::max(a, b));
    return block_rows_ +
           static_cast<Block>(std::lower_bound(pairs.begin(), pairs.end(), key) - pairs.begin());
  };
  diagonal_.resize(free_vertices_.size());
  for (std::uint32_t a = 0; a < free_vertices_.size(); ++a)
    diagonal_[a] = block(a, a);
  blocks_.resize(edges_.size());
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const std::uint32_t a = free_index_[edges_[e].i], b = free_index_[edges_[e].j];
    blocks_[e] = {block(a, a), block(b, b), block(a, b)};
  }
  // A hinge's pair (p, q) and (q, p) are one block: only p <= q is kept.
  hinge_blocks_.resize(hinges_.size());
  for (std::size_t k = 0; k < hinges_.size(); ++k)
    for (std::uint32_t p = 0; p < 4; ++p)
      for (std::uint32_t q = 0; q < 4; ++q)
        hinge_blocks_[k][4 * p + q] =
            q < p ? kFixed : block(free_index_[hinges_[k].v[p]], free_index_[hinges_[k].v[q]]);
  hinge_removed_.assign(hinges_.size(), 0);
  dihedral_blocks_.resize(dihedrals_.size());
  for (std::size_t k = 0; k < dihedrals_.size(); ++k)
    for (std::uint32_t p = 0; p < 4; ++p)
      for (std::uint32_t q = 0; q < 4; ++q)
        dihedral_blocks_[k][4 * p + q] =
            q < p ? kFixed
                  : block(free_index_[dihedrals_[k].v[p]], free_index_[dihedrals_[k].v[q]]);
  dihedral_removed_.assign(dihedrals_.size(), 0);
  body_diagonal_.resize(body_count_);
  body_vertex_.assign(body_count_, std::vector<Block>(free_rows));
  for (std::uint32_t b = 0; b < body_count_; ++b) {
    body_diagonal_[b] = block(free_rows + b, free_rows + b);
    for (std::uint32_t a = 0; a < free_rows; ++a)
      body_vertex_[b][a] = block(free_rows + b, a);
  }
  for (auto* v : {&body_start_, &body_target_, &body_x_, &body_trial_})
    v->assign(body_count_, Vec3::Zero());
  body_weight_.assign(body_count_, Real(0));
  removed_.assign(edges_.size(), 0);
  x0_.resize(n);
  y_.resize(n);
  trial_.resize(n);
  index_elements();
  gradient_.resize(3 * block_rows_);
  trial_gradient_.resize(3 * block_rows_);
  direction_.resize(3 * block_rows_);
}

Real ImplicitMembrane::gap(const MembraneContact& c, std::span<const Vec3> x,
                           std::span<const Vec3> bx) const {
  Vec3 point = c.point;
  if (c.body != kNoMembraneBody) point += bx[c.body] - body_start_[c.body];
  return c.normal.dot(x[c.vertex] - point);
}

Vec3 ImplicitMembrane::slip(const MembraneContact& c, std::span<const Vec3> x,
                            std::span<const Vec3> bx) const {
  Vec3 relative = x[c.vertex] - x0_[c.vertex] - c.motion;
  if (c.body != kNoMembraneBody) relative -= bx[c.body] - body_start_[c.body];
  return relative - c.normal.dot(relative) * c.normal;
}

bool ImplicitMembrane::rubs(const MembraneContact& c) const {
  return c.friction > 0 && c.normal_force > 0 && free_index_[c.vertex] != kFixed;
}

Real ImplicitMembrane::body_stop_gap(const MembraneBodyStop& r, std::span<const Vec3> bx) const {
  return r.gap0 + r.normal.dot(bx[r.body] - body_start_[r.body]);
}

Real ImplicitMembrane::evaluate(std::span<const Vec3> x, std::span<const Vec3> bx,
                                const ImplicitLoads& loads, Real contact_k, Dense& gradient,
                                const Executor& exec) {
  const std::span<const Vec3> force = loads.force;
  const Real inverse_h2 = 1 / (h_ * h_);
  evaluate_elements(x, exec);
  exec.for_chunks(free_vertices_.size(), kRowChunk, [&](std::size_t first, std::size_t last) {
    for (auto a = static_cast<std::uint32_t>(first); a < last; ++a) {
      const std::uint32_t v = free_vertices_[a];
      Vec3 g = mass_[v] * inverse_h2 * (x[v] - y_[v]);
      if (!force.empty()) g -= force[v];
      gradient.segment<3>(3 * a) = gather_elements(a, g);
    }
  });
  Real phi = 0;  // (unit: J), relative to x = y for the inertial and the external terms
  for (const std::uint32_t v : free_vertices_) {
    const Vec3 dx = x[v] - y_[v];
    phi += Real(0.5) * mass_[v] * inverse_h2 * dx.squaredNorm();
    if (!force.empty()) phi -= force[v].dot(dx);
  }
  phi = add_elements_energy(phi);
  const auto free_rows = static_cast<std::uint32_t>(free_vertices_.size());
  for (std::uint32_t b = 0; b < body_count_; ++b) {
    phi += Real(0.5) * body_weight_[b] * (bx[b] - body_target_[b]).squaredNorm();
    gradient.segment<3>(3 * (free_rows + b)) = body_weight_[b] * (bx[b] - body_target_[b]);
  }
  for (std::uint32_t k = 0; k < loads.contacts.size(); ++k) {
    const MembraneContact& c = loads.contacts[k];
    const std::uint32_t a = free_index_[c.vertex];
    if (a != kFixed && held_[a] == k) continue;  // held on its plane exactly: no penalty
    const Real g = gap(c, x, bx);
    if (g >= 0) continue;
    phi += Real(0.5) * contact_k * g * g;
    const Vec3 push = contact_k * g * c.normal;  // d/dx of k/2 g^2 (unit: N)
    if (a != kFixed) gradient.segment<3>(3 * a) += push;
    if (c.body != kNoMembraneBody) gradient.segment<3>(3 * (free_rows + c.body)) -= push;
  }
  for (const MembraneContact& c : loads.contacts) {  // friction, held rows too
    if (!rubs(c)) continue;
    const Vec3 u = slip(c, x, bx);
    const FrictionTerms f = friction_potential(c.friction * c.normal_force, u.norm(), stick_slip_);
    phi += f.energy;
    const Vec3 rub = f.per_slip * u;  // d/dx of mu lambda f0(|u|) (unit: N)
    gradient.segment<3>(3 * free_index_[c.vertex]) += rub;
    if (c.body != kNoMembraneBody) gradient.segment<3>(3 * (free_rows + c.body)) -= rub;
  }
  for (const MembraneBodyStop& r : loads.body_stops) {
    const Real g = body_stop_gap(r, bx);
    if (g >= 0) continue;
    phi += Real(0.5) * body_stop_k_ * g * g;
    gradient.segment<3>(3 * (free_rows + r.body)) += body_stop_k_ * g * r.normal;
  }
  for (const MembraneSupport& c : loads.supports) {
    const std::uint32_t a = free_index_[c.vertex];
    const Real g = c.normal.dot(x[c.vertex] - c.point);
    if (a == kFixed || (c.pushes_only && g >= 0)) continue;
    phi += Real(0.5) * c.stiffness * g * g;
    gradient.segment<3>(3 * a) += (c.stiffness * g) * c.normal;  // d/dx of k/2 g^2 (unit: N)
  }
  for (const MembraneAttachment& h : loads.attachments) {
    Vec3 target = h.target;
    if (h.body != kNoMembraneBody) target += bx[h.body] - body_start_[h.body];
    const Vec3 d = x[h.vertex] - target;
    phi += Real(0.5) * h.stiffness * d.squaredNorm();
    const Vec3 pull = h.stiffness * d;  // d/dx of k/2 |d|^2 (unit: N)
    const std::uint32_t a = free_index_[h.vertex];
    if (a != kFixed) gradient.segment<3>(3 * a) += pull;
    if (h.body != kNoMembraneBody) gradient.segment<3>(3 * (free_rows + h.body)) -= pull;
  }
  return phi;
}

bool ImplicitMembrane::factor_hessian(std::span<const Vec3> x, std::span<const Vec3> bx,
                                      const ImplicitLoads& loads, Real contact_k, bool exact) {
  auto add = [&](Block block, const Mat3& k, Real sign) {
    if (block != kFixed) hessian_[block] += sign * k;
  };
  if (constant_stale_) {  // the part no iterate changes: the masses and the hinges
    std::fill(hessian_.begin(), hessian_.end(), Mat3::Zero());
    const Real inverse_h2 = 1 / (h_ * h_);
    for (std::uint32_t a = 0; a < free_vertices_.size(); ++a)
      add(diagonal_[a], mass_[free_vertices_[a]] * inverse_h2 * Mat3::Identity(), 1);
    for (std::size_t k = 0; k < hinges_.size(); ++k) {
      if (hinge_removed_[k]) continue;
      const MembraneHinge& hinge = hinges_[k];
      for (std::uint32_t p = 0; p < 4; ++p)
        for (std::uint32_t q = 0; q < 4; ++q)
          add(hinge_blocks_[k][4 * p + q],
              hinge.stiffness * hinge.w[p] * hinge.w[q] * Mat3::Identity(), 1);
    }
    constant_hessian_ = hessian_;
    constant_stale_ = false;
  }
  std::copy(constant_hessian_.begin(), constant_hessian_.end(), hessian_.begin());
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    if (removed_[e]) continue;
    const Mat3 k = edge_stiffness(edges_[e].spring, x[edges_[e].i] - x[edges_[e].j], exact);
    add(blocks_[e].ii, k, 1);
    add(blocks_[e].jj, k, 1);
    add(blocks_[e].ij, k, -1);
  }
  // The dihedrals' Gauss-Newton blocks, k g_p g_q^T: a pair's block is stored as A(lo, hi), so
  // the one whose row is the higher block row takes the transpose.
  for (std::size_t k = 0; k < dihedrals_.size(); ++k) {
    if (dihedral_removed_[k]) continue;
    const MembraneDihedral& d = dihedrals_[k];
    const DihedralEval<Real> e = evaluate_dihedral(x[d.v[0]], x[d.v[1]], x[d.v[2]], x[d.v[3]],
                                                   dihedral_rest_[k][0], dihedral_rest_[k][1]);
    if (!e.valid) continue;
    for (std::uint32_t p = 0; p < 4; ++p) {
      for (std::uint32_t q = p; q < 4; ++q) {
        const std::uint32_t a = free_index_[d.v[p]], b = free_index_[d.v[q]];
        const Mat3 k_pq = d.stiffness * e.grad[p] * e.grad[q].transpose();
        add(dihedral_blocks_[k][4 * p + q], a <= b ? k_pq : Mat3(k_pq.transpose()), 1);
      }
    }
  }
  for (std::uint32_t b = 0; b < body_count_; ++b)
    add(body_diagonal_[b], body_weight_[b] * Mat3::Identity(), 1);
  for (std::uint32_t n = 0; n < loads.contacts.size(); ++n) {
    const MembraneContact& c = loads.contacts[n];
    const std::uint32_t a = free_index_[c.vertex];
    if (a != kFixed && held_[a] == n) continue;
    if (gap(c, x, bx) >= 0) continue;
    const Mat3 k = contact_k * c.normal * c.normal.transpose();
    if (a != kFixed) add(diagonal_[a], k, 1);
    if (c.body == kNoMembraneBody) continue;
    add(body_diagonal_[c.body], k, 1);
    if (a == kFixed) continue;
    add(body_vertex_[c.body][a], k, -1);
  }
  for (const MembraneContact& c : loads.contacts) {
    if (!rubs(c)) continue;
    const Vec3 u = slip(c, x, bx);
    const Real size = u.norm();
    const FrictionTerms f = friction_potential(c.friction * c.normal_force, size, stick_slip_);
    // per_slip across the slip in the plane, along_slip along it (at no slip, per_slip in both).
    Mat3 k = f.per_slip * (Mat3::Identity() - c.normal * c.normal.transpose());
    if (size > 0) {
      const Vec3 along = u / size;
      k += (f.along_slip - f.per_slip) * along * along.transpose();
    }
    const std::uint32_t a = free_index_[c.vertex];
    add(diagonal_[a], k, 1);
    if (c.body == kNoMembraneBody) continue;
    add(body_diagonal_[c.body], k, 1);
    add(body_vertex_[c.body][a], k, -1);
  }
  for (const MembraneBodyStop& r : loads.body_stops)
    if (body_stop_gap(r, bx) < 0)
      add(body_diagonal_[r.body], body_stop_k_ * r.normal * r.normal.transpose(), 1);
  for (const MembraneSupport& c : loads.supports) {
    const std::uint32_t a = free_index_[c.vertex];
    if (a != kFixed && (!c.pushes_only || c.normal.dot(x[c.vertex] - c.point) < 0))
      add(diagonal_[a], c.stiffness * c.normal * c.normal.transpose(), 1);
  }
  for (const MembraneAttachment& h : loads.attachments) {
    const Mat3 k = h.stiffness * Mat3::Identity();
    const std::uint32_t a = free_index_[h.vertex];
    if (a != kFixed) add(diagonal_[a], k, 1);
    if (h.body == kNoMembraneBody) continue;
    add(body_diagonal_[h.body], k, 1);
    if (a != kFixed) add(body_vertex_[h.body][a], k, -1);
  }
  filter_held(loads);
  return cholesky_.factorize({hessian_.data(), block_rows_},
                             {hessian_.data() + block_rows_, hessian_.size() - block_rows_});
}

void ImplicitMembrane::filter_held(const ImplicitLoads& loads) {
  const auto free_rows = static_cast<std::uint32_t>(free_vertices_.size());
  for (std::uint32_t a = 0; a < free_rows; ++a) {
    factored_held_[a] = held_[a] != kNone;
    if (held_[a] == kNone) continue;
    const Vec3& n = loads.contacts[held_[a]].normal;
    const Mat3 along = n * n.transpose();
    const Mat3 s = Mat3::Identity() - along;
    Mat3& d = hessian_[diagonal_[a]];
    // The normal's own stiffness the mass's: any positive value keeps the row's normal step zero.
    d = s * d * s + mass_[free_vertices_[a]] / (h_ * h_) * along;
  }
  for (std::size_t p = 0; p < pairs_.size(); ++p) {
    const auto [lo, hi] = pairs_[p];  // the block is A(lo, hi); A(hi, lo) its transpose
    const bool held_lo = lo < free_rows && held_[lo] != kNone;
    const bool held_hi = hi < free_rows && held_[hi] != kNone;
    if (!held_lo && !held_hi) continue;
    Mat3& b = hessian_[block_rows_ + p];
    if (held_lo) {
      const Vec3& n = loads.contacts[held_[lo]].normal;
      b = (Mat3::Identity() - n * n.transpose()) * b;
    }
    if (held_hi) {
      const Vec3& n = loads.contacts[held_[hi]].normal;
      b = b * (Mat3::Identity() - n * n.transpose());
    }
  }
}

Real ImplicitMembrane::largest_imbalance(const ImplicitLoads& loads) const {
  const auto free_rows = static_cast<std::uint32_t>(free_vertices_.size());
  Real largest = 0;
  for (std::uint32_t a = 0; a < block_rows_; ++a) {
    Vec3 g = gradient_.segment<3>(3 * a);
    if (a < free_rows && held_[a] != kNone) {
      // The plane supplies the normal part: held, the gradient's normal component is the
      // plane's reaction, pushing out while it is positive.
      const Vec3& n = loads.contacts[held_[a]].normal;
      g -= std::max(Real(0), n.dot(g)) * n;
    }
    largest = std::max(largest, g.norm());
  }
  return largest;
}

void ImplicitMembrane::project_crossing(const ImplicitLoads& loads, std::span<const Vec3> x) {
  std::fill(pending_.begin(), pending_.end(), kNone);
  for (std::uint32_t k = 0; k < loads.contacts.size(); ++k) {
    const MembraneContact& c = loads.contacts[k];
    const std::uint32_t a = free_index_[c.vertex];
    if (c.body != kNoMembraneBody || a == kFixed || held_[a] != kNone || released_[a] ||
        pending_[a] != kNone)
      continue;
    const Real at_trial = c.normal.dot(trial_[c.vertex] - c.point);
    // Only a vertex this trial carried through: one already under a plane (a second plane's
    // projection put it there) keeps the penalty, so the trial stays continuous in its length.
    if (at_trial >= 0 || c.normal.dot(x[c.vertex] - c.point) < 0) continue;
    trial_[c.vertex] -= at_trial * c.normal;
    pending_[a] = k;
  }
}

ImplicitStepReport ImplicitMembrane::step(std::span<Vec3> x, std::span<Vec3> v,
                                          const ImplicitLoads& loads,
                                          const ImplicitSolveParams& params) {
  const Executor serial(1);
  return step(x, v, loads, params, serial);
}

ImplicitStepReport ImplicitMembrane::step(std::span<Vec3> x, std::span<Vec3> v,
                                          const ImplicitLoads& loads,
                                          const ImplicitSolveParams& params, const Executor& exec) {
  const Vec3& gravity = loads.gravity;
  const Real contact_k = params.contact_stiffness;
  ImplicitStepReport report;
  const std::size_t n = mass_.size();
  if (x.size() != n || v.size() != n || !(loads.force.empty() || loads.force.size() == n))
    throw std::invalid_argument(
        "implicit membrane: positions, velocities and forces must be one "
        "per vertex (" +
        std::to_string(n) + ")");
  if (loads.bodies.size() != body_count_)
    throw std::invalid_argument("implicit membrane: " + std::to_string(loads.bodies.size()) +
                                " bodies given to a solver made for " +
                                std::to_string(body_count_));
  for (std::size_t k = 0; k < loads.contacts.size(); ++k) {
    const MembraneContact& c = loads.contacts[k];
    if (c.vertex >= mass_.size() || (c.body != kNoMembraneBody && c.body >= body_count_))
      throw std::invalid_argument("implicit membrane: contact " + std::to_string(k) +
                                  " names a vertex or a body out of range");
  }
  for (std::size_t k = 0; k < loads.attachments.size(); ++k) {
    const MembraneAttachment& h = loads.attachments[k];
    if (h.vertex >= mass_.size() || (h.body != kNoMembraneBody && h.body >= body_count_) ||
        !(h.stiffness > 0))
      throw std::invalid_argument("implicit membrane: attachment " + std::to_string(k) +
                                  " names a vertex or a body out of range, or has no stiffness");
  }
  for (std::size_t k = 0; k < loads.supports.size(); ++k)
    if (loads.supports[k].vertex >= mass_.size() || !(loads.supports[k].stiffness > 0))
      throw std::invalid_argument("implicit membrane: support " + std::to_string(k) +
                                  " names a vertex out of range, or has no stiffness");
  for (std::size_t k = 0; k < loads.body_stops.size(); ++k)
    if (loads.body_stops[k].body >= body_count_)
      throw std::invalid_argument("implicit membrane: body stop " + std::to_string(k) +
                                  " names a body out of range");
  body_stop_k_ = params.body_stop_stiffness;
  stick_slip_ = params.stick_slip;
  for (std::size_t k = 0; k < loads.contacts.size(); ++k) {
    const MembraneContact& c = loads.contacts[k];
    if (!(c.friction >= 0) || !(c.normal_force >= 0) || !c.motion.allFinite())
      throw std::invalid_argument("implicit membrane: contact " + std::to_string(k) +
                                  ": friction and normal force must not be negative, the motion "
                                  "finite");
    if (c.friction > 0 && c.normal_force > 0 && !(stick_slip_ > 0))
      throw std::invalid_argument(
          "implicit membrane: friction needs a positive stick-slip distance");
  }
  for (std::uint32_t b = 0; b < body_count_; ++b) {
    const MembraneBody& body = loads.bodies[b];
    if (!(body.stiffness >= 0) || !(body.damping >= 0) || !(body.stiffness + body.damping > 0))
      throw std::invalid_argument("implicit membrane: body " + std::to_string(b) +
                                  ": stiffness and damping must not be negative, nor both zero");
    // k/2 |o - anchor|^2 + c/(2h) |o - o_start|^2 = w/2 |o - target|^2 + constant.
    const Real viscous = body.damping / h_;
    body_weight_[b] = viscous + body.stiffness;
    body_target_[b] = (viscous * body.position + body.stiffness * body.anchor) / body_weight_[b];
    body_start_[b] = body_x_[b] = body_trial_[b] = body.position;
  }
  for (std::uint32_t u : free_vertices_) {
    x0_[u] = x[u];
    y_[u] = x[u] + h_ * v[u] + h_ * h_ * gravity;  // the inertial prediction
    // The first iterate: the motion carried on, without gravity's h^2 g, which a membrane at
    // rest does not follow (its tension holds it): starting from y would start 0.25 mm out of
    // balance at every vertex and cost the stiff membrane a damped Newton step or two.
    x[u] = x[u] + h_ * v[u];
  }
  // The active set starts with the vertices the first iterate finds on or under a fixed plane,
  // put on it.
  std::fill(held_.begin(), held_.end(), kNone);
  std::fill(released_.begin(), released_.end(), 0);
  for (std::uint32_t k = 0; k < loads.contacts.size(); ++k) {
    const MembraneContact& c = loads.contacts[k];
    const std::uint32_t a = free_index_[c.vertex];
    if (!params.hold_fixed_planes || c.body != kNoMembraneBody || a == kFixed || held_[a] != kNone)
      continue;
    const Real g = c.normal.dot(x[c.vertex] - c.point);
    if (g > params.hold_distance) continue;
    x[c.vertex] -= g * c.normal;
    held_[a] = k;
  }
  const auto free_rows = static_cast<std::uint32_t>(free_vertices_.size());
  auto held_changed = [&] {
    for (std::uint32_t a = 0; a < free_rows; ++a)
      if ((held_[a] != kNone) != bool(factored_held_[a])) return true;
    return false;
  };
  Real phi = evaluate(x, body_x_, loads, contact_k, gradient_, exec);
  report.residual = largest_imbalance(loads);
  std::copy(x.begin(), x.end(), trial_.begin());
  // Modified Newton: the last factorisation (of an earlier iterate, or of the last step) is kept
  // while it converges fast and holds the same vertices, and refactored when not.
  bool refactor = !factored_ || held_changed();
  bool for_active_set = refactor;      // why the next factorisation is made
  auto along_planes = [&](Dense& d) {  // a held row's normal part taken out
    for (std::uint32_t a = 0; a < free_rows; ++a) {
      if (held_[a] == kNone) continue;
      const Vec3& normal = loads.contacts[held_[a]].normal;
      d.segment<3>(3 * a) -= normal.dot(d.segment<3>(3 * a)) * normal;
    }
  };
  while (report.iterations < params.max_iterations && report.residual > params.tolerance) {
    if (refactor) {
      // The exact Hessian where it is positive definite, else (compression the bending and the
      // mass cannot hold) the clamped one.
      const std::uint32_t before_factoring = report.factorizations;
      bool factored = factor_hessian(x, body_x_, loads, contact_k, true);
      ++report.factorizations;
      if (!factored) {
        factored = factor_hessian(x, body_x_, loads, contact_k, false);
        ++report.factorizations;
      }
      if (for_active_set)
        report.active_set_factorizations += report.factorizations - before_factoring;
      if (!factored) {
        report.ok = false;
        factored_ = false;
        break;
      }
      factored_ = true;
    }
    ++report.iterations;
    direction_ = -gradient_;  // the step solves H d = -grad
    along_planes(direction_);
    cholesky_.solve({direction_.data(), static_cast<std::size_t>(direction_.size())});
    along_planes(direction_);  // exact, whatever normals the kept factorisation held
    // Backtracking (Armijo): the full step unless it raises Phi. The matrix is positive definite
    // (whatever iterate it was made at), so the direction descends.
    Real slope = 0;  // a plain loop: GCC 12 warns falsely in Eigen's AVX-512 dot product
    for (Eigen::Index k = 0; k < gradient_.size(); ++k)
      slope += gradient_[k] * direction_[k];
    Real alpha = 1, trial_phi = 0;
    bool accepted = false;
    for (int halving = 0; halving < 30 && !accepted; ++halving, alpha *= Real(0.5)) {
      for (std::uint32_t a = 0; a < free_rows; ++a)
        trial_[free_vertices_[a]] = x[free_vertices_[a]] + alpha * direction_.segment<3>(3 * a);
      for (std::uint32_t b = 0; b < body_count_; ++b)
        body_trial_[b] = body_x_[b] + alpha * direction_.segment<3>(3 * (free_rows + b));
      if (params.hold_fixed_planes) project_crossing(loads, x);
      // Phi and its gradient at the trial together: the full step is nearly always taken.
      trial_phi = evaluate(trial_, body_trial_, loads, contact_k, trial_gradient_, exec);
      accepted = trial_phi <= phi + Real(1e-4) * alpha * slope;
    }
    if (!accepted) {
      if (refactor) break;  // a fresh Newton step finds no descent: solved to Phi's rounding
      refactor = true;
      for_active_set = false;
      continue;
    }
    // The loop halves alpha once more after the accepted trial: alpha / 2 was taken.
    if (alpha < Real(0.5)) ++report.shortened_iterations;
    for (std::uint32_t u : free_vertices_)
      x[u] = trial_[u];
    body_x_ = body_trial_;
    phi = trial_phi;
    gradient_.swap(trial_gradient_);
    // The vertices the trial put on planes are held from here; those their plane would have to
    // pull are let go for the rest of the step.
    for (std::uint32_t a = 0; a < free_rows; ++a) {
      if (pending_[a] != kNone) held_[a] = pending_[a];
      if (held_[a] == kNone) continue;
      if (loads.contacts[held_[a]].normal.dot(gradient_.segment<3>(3 * a)) < -params.tolerance) {
        held_[a] = kNone;
        released_[a] = 1;
      }
    }
    const Real before = report.residual;
    report.residual = largest_imbalance(loads);
    // A matrix that no longer cuts the imbalance fast enough is refactored at the new iterate, as
    // is one whose held rows are not the active set's (the matrix filters them).
    for_active_set = held_changed();
    refactor = for_active_set || report.residual > params.kept_matrix_ratio * before;
  }
  for (std::uint32_t u : free_vertices_)
    v[u] = (x[u] - x0_[u]) / h_;
  for (std::uint32_t b = 0; b < body_count_; ++b)
    loads.bodies[b].position = body_x_[b];
  contact_forces_.resize(loads.contacts.size());
  contact_frictions_.resize(loads.contacts.size());
  for (std::uint32_t k = 0; k < loads.contacts.size(); ++k) {
    const MembraneContact& c = loads.contacts[k];
    contact_frictions_[k] = Vec3::Zero();
    if (rubs(c)) {
      const Vec3 u = slip(c, x, body_x_);
      contact_frictions_[k] =
          -friction_potential(c.friction * c.normal_force, u.norm(), stick_slip_).per_slip * u;
    }
    const std::uint32_t a = free_index_[c.vertex];
    if (a != kFixed && held_[a] == k) {
      contact_forces_[k] = std::max(Real(0), c.normal.dot(gradient_.segment<3>(3 * a)));
    } else {
      const Real g = gap(c, x, body_x_);
      contact_forces_[k] = g < 0 ? -contact_k * g : Real(0);
    }
  }
  return report;
}

void ImplicitMembrane::remove_hinge(std::size_t k) {
  if (k >= hinges_.size()) return;
  hinge_removed_[k] = 1;
  factored_ = false;
  constant_stale_ = true;
}

void ImplicitMembrane::remove_dihedral(std::size_t k) {
  if (k >= dihedrals_.size()) return;
  dihedral_removed_[k] = 1;
  factored_ = false;
}

void ImplicitMembrane::scale_edge(std::size_t e, Real factor) {
  if (e >= edges_.size() || !(factor > 0)) return;
  edges_[e].spring.toe_stiffness *= factor;
  edges_[e].spring.linear_stiffness *= factor;
  factored_ = false;
}

void ImplicitMembrane::remove_edge(std::size_t e) {
  if (e >= edges_.size()) return;
  removed_[e] = 1;
  factored_ = false;
}

}  // namespace imasim::physics
