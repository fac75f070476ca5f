#include "surgery/fascia_fragments.hpp"

#include <algorithm>
#include <numeric>
#include <vector>

#include "physics/mesh_constraints.hpp"

namespace imasim::surgery {
namespace {

// Union-find over the mesh's vertices (path halving).
std::uint32_t root_of(std::vector<std::uint32_t>& parent, std::uint32_t v) {
  while (parent[v] != v)
    v = parent[v] = parent[parent[v]];
  return v;
}

}  // namespace

FragmentRemoval vaporise_free_fragments(tissue::TissueWorld& w, const FragmentParams& params,
                                        FasciaCutter& cutter) {
  FragmentRemoval out;
  const tissue::MeshObject& m = w.meshes[cutter.mesh];
  const physics::Particles& P = w.state.particles;
  const std::uint32_t first = m.first_particle, n = m.particle_count;
  const auto faces = static_cast<std::uint32_t>(m.triangles.size());

  std::vector<std::uint32_t> parent(n);
  std::iota(parent.begin(), parent.end(), 0u);
  for (const geometry::Triangle& t : m.triangles) {
    for (int k = 1; k < 3; ++k) {
      // Both roots afresh for each corner: the first union may have made t[0]'s root a child.
      const std::uint32_t a = root_of(parent, t[0]), b = root_of(parent, t[k]);
      if (a != b) parent[std::max(a, b)] = std::min(a, b);  // the lower index is the root
    }
  }
  // Pieces by their root vertex: rest area, and whether anything holds them.
  std::vector<Real> area(n, 0);
  std::vector<std::uint8_t> held(n, 0);
  std::vector<std::uint32_t> piece(faces);
  for (std::uint32_t f = 0; f < faces; ++f) {
    piece[f] = root_of(parent, m.triangles[f][0]);
    area[piece[f]] += physics::rest_triangle_area(P, first, m.triangles[f]);
  }
  auto hold_particle = [&](std::uint32_t i) {
    if (i >= first && i < first + n) held[root_of(parent, i - first)] = 1;
  };
  for (std::uint32_t v = 0; v < n; ++v) {
    const std::uint32_t i = first + v;
    if (P.is_fixed(i) || (i < w.held.size() && w.held[i])) hold_particle(i);
  }
  // A coupling moves its destination after its source (eq. 8-9): a piece that is a destination
  // is held; one that is only a source holds nothing. A destination that held fat drives (beta
  // by manipulation) is held only while that fat is held, and one that is left alone then (no
  // decay) is not moved at all.
  const tissue::CouplingFlags flags{w.held, w.manipulated};
  for (const tissue::OffsetCoupling& c : w.couplings) {
    for (const auto& pair : c.pairs) {
      const bool moved = tissue::pair_follows(c, pair.first, flags) || c.decay != 1;
      if (c.beta != tissue::Beta::manipulated || moved) hold_particle(pair.second);
    }
  }
  // The sheet: the largest piece, never removed.
  std::uint32_t sheet = 0;
  for (std::uint32_t f = 0; f < faces; ++f)
    if (area[piece[f]] > area[sheet]) sheet = piece[f];

  std::vector<std::uint32_t> removed;
  std::vector<std::uint8_t> counted(n, 0);
  for (std::uint32_t f = 0; f < faces; ++f) {
    const std::uint32_t r = piece[f];
    if (r == sheet || held[r] || !(area[r] <= params.max_area)) continue;
    removed.push_back(f);
    ++out.triangles;
    if (!counted[r]) {
      counted[r] = 1;
      ++out.fragments;
      out.area += area[r];
    }
  }
  if (removed.empty()) return out;
  const tissue::TopologyChange change = tissue::remove_mesh_triangles(w, cutter.mesh, removed);
  out.status = change.status;
  if (change.status != tissue::EditStatus::applied) {
    out.fragments = out.triangles = 0;
    out.area = 0;
    return out;
  }
  // The cutter forgets the edges and vertices that went.
  const tissue::MeshObject& after = w.meshes[cutter.mesh];
  std::erase_if(cutter.pending,
                [&](std::uint64_t key) { return after.edges.find(key) == after.edges.end(); });
  std::vector<std::uint8_t> used(after.particle_count, 0);
  for (const geometry::Triangle& t : after.triangles)
    for (std::uint32_t v : t)
      used[v] = 1;
  std::erase_if(cutter.cut_vertices, [&](std::uint32_t v) { return v >= used.size() || !used[v]; });
  return out;
}

}  // namespace imasim::surgery
