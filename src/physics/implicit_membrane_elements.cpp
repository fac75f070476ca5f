// The implicit membrane's elements (edges, hinges, dihedrals) evaluated apart and gathered per
// row: the dihedrals' geometry is most of a step's evaluation (the vessel's tube: about 6 % of a
// session's step), and element by element it runs on the executor's threads. Each element's
// terms are computed the same way on any thread, and each row adds them in element order, as
// the serial scatter did, so the result does not depend on the thread count.
#include <algorithm>

#include "physics/dihedral_constraint.hpp"
#include "physics/implicit_membrane.hpp"

namespace imasim::physics {

namespace {

// Fixed slices of every element list: a thread takes whole slices, whatever the thread count.
constexpr std::size_t kElementSlices = 16;

// CSR of the rows an element list reaches: for each element in order, for each of its vertices
// that is free, (row, entry(element, slot)).
template <class ForEach>
void index_rows(std::size_t rows, const ForEach& for_each, std::vector<std::uint32_t>& start,
                std::vector<std::uint32_t>& entries) {
  start.assign(rows + 1, 0);
  for_each([&](std::uint32_t row, std::uint32_t) { ++start[row + 1]; });
  for (std::size_t r = 0; r < rows; ++r)
    start[r + 1] += start[r];
  entries.assign(start[rows], 0);
  std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
  for_each([&](std::uint32_t row, std::uint32_t entry) { entries[next[row]++] = entry; });
}

}  // namespace

void ImplicitMembrane::index_elements() {
  const std::size_t rows = free_vertices_.size();
  index_rows(
      rows,
      [&](const auto& add) {
        for (std::uint32_t e = 0; e < edges_.size(); ++e) {
          if (free_index_[edges_[e].i] != kFixed) add(free_index_[edges_[e].i], 2 * e);
          if (free_index_[edges_[e].j] != kFixed) add(free_index_[edges_[e].j], 2 * e + 1);
        }
      },
      row_edges_start_, row_edges_);
  // Hinges and dihedrals alike: four vertices each, entry 4 k + p.
  auto four_vertices = [&](const auto& elements) {
    return [this, &elements](const auto& add) {
      for (std::uint32_t k = 0; k < elements.size(); ++k)
        for (std::uint32_t p = 0; p < 4; ++p)
          if (free_index_[elements[k].v[p]] != kFixed)
            add(free_index_[elements[k].v[p]], 4 * k + p);
    };
  };
  index_rows(rows, four_vertices(hinges_), row_hinges_start_, row_hinges_);
  index_rows(rows, four_vertices(dihedrals_), row_dihedrals_start_, row_dihedrals_);
  edge_terms_.assign(edges_.size(), 0);
  edge_energy_.assign(edges_.size(), 0);
  edge_gradient_.assign(edges_.size(), Vec3::Zero());
  hinge_curvature_.assign(hinges_.size(), Vec3::Zero());
  dihedral_terms_.assign(dihedrals_.size(), 0);
  dihedral_value_.assign(dihedrals_.size(), 0);
  dihedral_grad_.assign(dihedrals_.size(),
                        {Vec3::Zero(), Vec3::Zero(), Vec3::Zero(), Vec3::Zero()});
}

void ImplicitMembrane::evaluate_elements(std::span<const Vec3> x, const Executor& exec) {
  const std::size_t edges = edges_.size(), hinges = hinges_.size(), dihedrals = dihedrals_.size();
  exec.for_chunks(kElementSlices, 1, [&](std::size_t first, std::size_t last) {
    for (std::size_t s = first; s < last; ++s) {
      for (std::size_t e = edges * s / kElementSlices; e < edges * (s + 1) / kElementSlices; ++e) {
        edge_terms_[e] = 0;
        if (removed_[e]) continue;
        const MembraneEdge& edge = edges_[e];
        const Vec3 d = x[edge.i] - x[edge.j];
        const Real l = d.norm();
        edge_energy_[e] = energy(edge.spring, l);
        edge_terms_[e] = 1;
        if (!(l > Real(1e-12))) continue;
        edge_gradient_[e] = tension(edge.spring, l) / l * d;  // dE/dx_i (unit: N)
        edge_terms_[e] = 2;
      }
      for (std::size_t k = hinges * s / kElementSlices; k < hinges * (s + 1) / kElementSlices;
           ++k) {
        const MembraneHinge& hinge = hinges_[k];
        Vec3 sum = Vec3::Zero();
        for (std::uint32_t p = 0; p < 4; ++p)
          sum += hinge.w[p] * x[hinge.v[p]];
        hinge_curvature_[k] = sum;
      }
      for (std::size_t k = dihedrals * s / kElementSlices; k < dihedrals * (s + 1) / kElementSlices;
           ++k) {
        dihedral_terms_[k] = 0;
        if (dihedral_removed_[k]) continue;
        const MembraneDihedral& d = dihedrals_[k];
        const DihedralEval<Real> e = evaluate_dihedral(x[d.v[0]], x[d.v[1]], x[d.v[2]], x[d.v[3]],
                                                       dihedral_rest_[k][0], dihedral_rest_[k][1]);
        if (!e.valid) continue;  // a degenerate wing: its angle, and so its bending, undefined
        dihedral_value_[k] = e.value;
        dihedral_grad_[k] = e.grad;
        dihedral_terms_[k] = 1;
      }
    }
  });
}

Vec3 ImplicitMembrane::gather_elements(std::uint32_t row, Vec3 g) const {
  for (std::uint32_t q = row_edges_start_[row]; q < row_edges_start_[row + 1]; ++q) {
    const std::uint32_t e = row_edges_[q] >> 1;
    if (edge_terms_[e] != 2) continue;
    if (row_edges_[q] & 1)
      g -= edge_gradient_[e];
    else
      g += edge_gradient_[e];
  }
  for (std::uint32_t q = row_hinges_start_[row]; q < row_hinges_start_[row + 1]; ++q) {
    const std::uint32_t k = row_hinges_[q] >> 2, p = row_hinges_[q] & 3;
    if (hinge_removed_[k]) continue;
    const Vec3 kappa = hinges_[k].stiffness * hinge_curvature_[k];  // (unit: N)
    g += hinges_[k].w[p] * kappa;
  }
  for (std::uint32_t q = row_dihedrals_start_[row]; q < row_dihedrals_start_[row + 1]; ++q) {
    const std::uint32_t k = row_dihedrals_[q] >> 2, p = row_dihedrals_[q] & 3;
    if (!dihedral_terms_[k]) continue;
    const Real moment = dihedrals_[k].stiffness * dihedral_value_[k];  // k (theta - theta_0) (N m)
    g += moment * dihedral_grad_[k][p];
  }
  return g;
}

Real ImplicitMembrane::add_elements_energy(Real phi) const {
  for (std::size_t e = 0; e < edges_.size(); ++e)
    if (edge_terms_[e]) phi += edge_energy_[e];
  for (std::size_t k = 0; k < hinges_.size(); ++k)
    if (!hinge_removed_[k])
      phi += Real(0.5) * hinges_[k].stiffness * hinge_curvature_[k].squaredNorm();
  for (std::size_t k = 0; k < dihedrals_.size(); ++k)
    if (dihedral_terms_[k])
      phi += Real(0.5) * dihedrals_[k].stiffness * dihedral_value_[k] * dihedral_value_[k];
  return phi;
}

}  // namespace imasim::physics
