#include "surgery/fascia_cut.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/mesh_checks.hpp"

namespace imasim::surgery {
namespace {

using geometry::kNoFace;
using geometry::Triangle;
using tissue::edge_key;

constexpr std::uint32_t kNone = 0xffffffffu;

// The swept quadrilateral: plane, extent test and bounding box.
struct SweptArea {
  Vec3 origin, blade, motion, normal;
  Real a11 = 0, a12 = 0, a22 = 0, det = 0;
  Real margin_u = 0, margin_w = 0, epsilon = 0;
  Vec3 low, high;

  Real signed_distance(const Vec3& x) const { return normal.dot(x - origin); }
  // Inside the quadrilateral (within epsilon of its edges) and within epsilon of its plane.
  bool contains(const Vec3& x) const {
    const Vec3 r = x - origin;
    const Real rb = r.dot(blade), rd = r.dot(motion);
    const Real u = (a22 * rb - a12 * rd) / det, w = (a11 * rd - a12 * rb) / det;
    return u >= -margin_u && u <= 1 + margin_u && w >= -margin_w && w <= 1 + margin_w &&
           std::abs(signed_distance(x)) <= epsilon;
  }
};

bool make_swept_area(const CuttingGeometry& g, Real epsilon, SweptArea& s) {
  const Vec3 n = g.blade.cross(g.motion);
  const Real lb = g.blade.norm(), ld = g.motion.norm();
  // A blade moving along itself, or not moving, sweeps no area: nothing to cut this step.
  if (!(n.norm() > Real(1e-6) * lb * ld) || !(lb > 0) || !(ld > 0) || !n.allFinite()) return false;
  s.origin = g.origin;
  s.blade = g.blade;
  s.motion = g.motion;
  s.normal = n.normalized();
  s.a11 = lb * lb;
  s.a12 = g.blade.dot(g.motion);
  s.a22 = ld * ld;
  s.det = s.a11 * s.a22 - s.a12 * s.a12;
  s.epsilon = epsilon;
  s.margin_u = epsilon / lb;
  s.margin_w = epsilon / ld;
  s.low = s.high = g.origin;
  for (const Vec3& c :
       {Vec3(g.origin + g.blade), Vec3(g.origin + g.motion), Vec3(g.origin + g.blade + g.motion)}) {
    s.low = s.low.cwiseMin(c);
    s.high = s.high.cwiseMax(c);
  }
  s.low.array() -= 2 * epsilon;
  s.high.array() += 2 * epsilon;
  return s.det > 0;
}

struct Split {
  std::uint64_t key = 0;
  Real t = 0;  // from the edge's lower-numbered vertex
  bool kept = true;
  std::uint32_t vertex = kNone;  // mesh-local index once made
};

struct Planner {
  const tissue::TissueWorld& world;
  const tissue::MeshObject& mesh;
  const FasciaCutParams& params;
  const SweptArea& area;
  std::vector<std::int8_t> side;     // -1, 0 (on the plane), +1; 2 = not yet classified
  std::vector<std::uint8_t> on_cut;  // on the plane and inside the swept area
  std::vector<std::uint32_t> candidates;
  std::vector<Split> splits;                       // sorted by key
  const std::vector<std::uint32_t>& cut_vertices;  // earlier steps' (FasciaCutter)

  Vec3 position(std::uint32_t v) const {
    return world.state.particles.position[mesh.first_particle + v];
  }
  Vec3 rest(std::uint32_t v) const {
    return world.state.particles.rest_position[mesh.first_particle + v];
  }
  void classify(std::uint32_t v) {
    if (side[v] != 2) return;
    const Real d = area.signed_distance(position(v));
    side[v] = std::abs(d) < params.proximity ? 0 : (d > 0 ? 1 : -1);
    on_cut[v] = side[v] == 0 && (area.contains(position(v)) ||
                                 std::binary_search(cut_vertices.begin(), cut_vertices.end(), v));
  }
  Split* find_split(std::uint32_t a, std::uint32_t b) {
    const std::uint64_t key = edge_key(a, b);
    const auto it = std::lower_bound(splits.begin(), splits.end(), key,
                                     [](const Split& s, std::uint64_t k) { return s.key < k; });
    return it != splits.end() && it->key == key && it->kept ? &*it : nullptr;
  }
  // Rest position of a split point on edge (a, b).
  Vec3 split_rest(const Split& s) const {
    const auto lo = static_cast<std::uint32_t>(s.key >> 32), hi = static_cast<std::uint32_t>(s.key);
    return (1 - s.t) * rest(lo) + s.t * rest(hi);
  }
  bool good(const Vec3& a, const Vec3& b, const Vec3& c) const {
    return geometry::triangle_area(a, b, c) >= params.min_area &&
           geometry::smallest_angle(a, b, c) >= params.min_angle;
  }
};

// How one triangle divides: pieces as vertex references, where a reference >= 0x80000000 names a
// split (index into the planner's splits) and otherwise a mesh vertex.
constexpr std::uint32_t kSplitBit = 0x80000000u;
struct Division {
  std::uint32_t pieces[3][3] = {};
  int piece_count = 1;
  std::uint32_t cut_from = kNone, cut_to = kNone;  // the cut edge inside the triangle, if any
  Split* splits[3] = {nullptr, nullptr, nullptr};  // per edge k = (t[k], t[k+1])
};

Division divide(Planner& pl, const Triangle& t) {
  Division d;
  int count = 0;
  for (int k = 0; k < 3; ++k) {
    d.splits[k] = pl.find_split(t[k], t[(k + 1) % 3]);
    count += d.splits[k] ? 1 : 0;
  }
  auto ref = [&](int k) {  // the split on edge k as a reference
    return kSplitBit | static_cast<std::uint32_t>(d.splits[k] - pl.splits.data());
  };
  if (count == 0) {
    d.pieces[0][0] = t[0];
    d.pieces[0][1] = t[1];
    d.pieces[0][2] = t[2];
    for (int k = 0; k < 3; ++k) {  // a cut along an existing edge: both ends on the cut
      const std::uint32_t a = t[k], b = t[(k + 1) % 3], o = t[(k + 2) % 3];
      if (pl.on_cut[a] && pl.on_cut[b] && pl.side[o] != 0) {
        d.cut_from = a;
        d.cut_to = b;
      }
    }
    return d;
  }
  if (count == 1) {
    int k = 0;
    while (!d.splits[k])
      ++k;
    const std::uint32_t a = t[k], b = t[(k + 1) % 3], o = t[(k + 2) % 3], p = ref(k);
    d.piece_count = 2;
    const std::uint32_t p0[3] = {a, p, o}, p1[3] = {p, b, o};
    std::copy(p0, p0 + 3, d.pieces[0]);
    std::copy(p1, p1 + 3, d.pieces[1]);
    if (pl.on_cut[o]) {
      d.cut_from = o;
      d.cut_to = p;
    }
    return d;
  }
  // Two splits: on edges k (t[k] -> apex) and k + 1 (apex -> t[k+2]).
  int k = 0;
  while (!(d.splits[k] && d.splits[(k + 1) % 3]))
    ++k;
  const std::uint32_t a = t[k], apex = t[(k + 1) % 3], c = t[(k + 2) % 3];
  const std::uint32_t p = ref(k), q = ref((k + 1) % 3);
  d.piece_count = 3;
  const std::uint32_t tip[3] = {p, apex, q};
  std::copy(tip, tip + 3, d.pieces[0]);
  d.cut_from = p;
  d.cut_to = q;
  // The quadrilateral (a, p, q, c) by the diagonal that keeps the larger smallest angle.
  auto at = [&](std::uint32_t r) {
    return r & kSplitBit ? pl.split_rest(pl.splits[r & ~kSplitBit]) : pl.rest(r);
  };
  const Real via_aq = std::min(geometry::smallest_angle(at(a), at(p), at(q)),
                               geometry::smallest_angle(at(a), at(q), at(c)));
  const Real via_pc = std::min(geometry::smallest_angle(at(a), at(p), at(c)),
                               geometry::smallest_angle(at(p), at(q), at(c)));
  if (via_aq >= via_pc) {
    const std::uint32_t p1[3] = {a, p, q}, p2[3] = {a, q, c};
    std::copy(p1, p1 + 3, d.pieces[1]);
    std::copy(p2, p2 + 3, d.pieces[2]);
  } else {
    const std::uint32_t p1[3] = {a, p, c}, p2[3] = {p, q, c};
    std::copy(p1, p1 + 3, d.pieces[1]);
    std::copy(p2, p2 + 3, d.pieces[2]);
  }
  return d;
}

// True when every piece of the division is well shaped (rest positions); else drops the split
// of this triangle nearest a vertex and returns false.
bool accept_or_drop(Planner& pl, Division& d) {
  if (d.piece_count == 1) return true;
  auto at = [&](std::uint32_t r) {
    return r & kSplitBit ? pl.split_rest(pl.splits[r & ~kSplitBit]) : pl.rest(r);
  };
  bool ok = true;
  for (int i = 0; i < d.piece_count; ++i)
    ok = ok && pl.good(at(d.pieces[i][0]), at(d.pieces[i][1]), at(d.pieces[i][2]));
  if (ok) return true;
  Split* worst = nullptr;
  for (Split* s : d.splits) {
    if (s && (!worst || std::min(s->t, 1 - s->t) < std::min(worst->t, 1 - worst->t))) worst = s;
  }
  worst->kept = false;
  return false;
}

// Plans and applies the division of the crossed triangles. Appends the cut edges (keys in the
// new numbering) to `cut_edges`.
tissue::TopologyChange split_crossed_triangles(tissue::TissueWorld& world, Planner& pl,
                                               std::uint32_t mesh_index,
                                               std::vector<std::uint64_t>& cut_edges,
                                               std::vector<std::uint64_t>& pending,
                                               FasciaCutResult& result) {
  const tissue::MeshObject& m = pl.mesh;
  // Crossed edges inside the swept area.
  for (std::uint32_t f : pl.candidates) {
    const Triangle& t = m.triangles[f];
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = t[k], b = t[(k + 1) % 3];
      if (a > b) std::swap(a, b);
      if (pl.side[a] * pl.side[b] >= 0) continue;
      const Real da = pl.area.signed_distance(pl.position(a));
      const Real db = pl.area.signed_distance(pl.position(b));
      const Real s = da / (da - db);
      if (!pl.area.contains((1 - s) * pl.position(a) + s * pl.position(b))) continue;
      pl.splits.push_back({edge_key(a, b), s});
    }
  }
  std::sort(pl.splits.begin(), pl.splits.end(),
            [](const Split& x, const Split& y) { return x.key < y.key; });
  pl.splits.erase(std::unique(pl.splits.begin(), pl.splits.end(),
                              [](const Split& x, const Split& y) { return x.key == y.key; }),
                  pl.splits.end());
  // Drop splits that would make poor pieces until every division is acceptable.
  for (bool changed = true; changed;) {
    changed = false;
    for (std::uint32_t f : pl.candidates) {
      Division d = divide(pl, m.triangles[f]);
      if (!accept_or_drop(pl, d)) changed = true;
    }
  }
  tissue::MeshEdit edit;
  const std::uint32_t n = m.particle_count;
  for (Split& s : pl.splits) {
    if (!s.kept) continue;
    s.vertex = n + static_cast<std::uint32_t>(edit.vertices.size());
    edit.vertices.push_back(
        {static_cast<std::uint32_t>(s.key >> 32), static_cast<std::uint32_t>(s.key), s.t});
  }
  auto vertex_of = [&](std::uint32_t r) {
    return r & kSplitBit ? pl.splits[r & ~kSplitBit].vertex : r;
  };
  for (std::uint32_t f : pl.candidates) {
    const Division d = divide(pl, m.triangles[f]);
    if (d.cut_from != kNone)
      cut_edges.push_back(edge_key(vertex_of(d.cut_from), vertex_of(d.cut_to)));
    if (d.piece_count == 1) continue;
    auto tri = [&](int i) {
      return Triangle{vertex_of(d.pieces[i][0]), vertex_of(d.pieces[i][1]),
                      vertex_of(d.pieces[i][2])};
    };
    edit.replaced.emplace_back(f, tri(0));
    for (int i = 1; i < d.piece_count; ++i)
      edit.added.push_back({tri(i), f});
  }
  result.edges_split = static_cast<std::uint32_t>(edit.vertices.size());
  tissue::TopologyChange change = tissue::apply_mesh_edit(world, mesh_index, edit);
  if (change.status != tissue::EditStatus::applied) return change;
  result.new_vertices = edit.vertices;
  // A pending cut edge that is split now continues as its two halves.
  for (const Split& s : pl.splits) {
    if (!s.kept) continue;
    const auto it = std::lower_bound(pending.begin(), pending.end(), s.key);
    if (it == pending.end() || *it != s.key) continue;
    pending.erase(it);
    cut_edges.push_back(edge_key(static_cast<std::uint32_t>(s.key >> 32), s.vertex));
    cut_edges.push_back(edge_key(s.vertex, static_cast<std::uint32_t>(s.key)));
  }
  return change;
}

// The fan of triangles around v, starting from `start`, as sectors: triangles joined across
// edges (v, x) that are not cut. Returns the sector of each triangle in `fan`.
void fan_sectors(const tissue::MeshObject& m, std::uint32_t v, std::uint32_t start,
                 const std::vector<std::uint64_t>& cut,
                 std::vector<std::pair<std::uint32_t, std::uint32_t>>& fan) {
  fan.clear();
  auto is_cut = [&](std::uint64_t key) { return std::binary_search(cut.begin(), cut.end(), key); };
  // Gather the whole fan across every edge (v, x), then label sectors across uncut ones.
  std::vector<std::uint32_t> stack = {start};
  std::vector<std::uint32_t> all;
  while (!stack.empty()) {
    const std::uint32_t f = stack.back();
    stack.pop_back();
    if (std::find(all.begin(), all.end(), f) != all.end()) continue;
    all.push_back(f);
    for (std::uint32_t x : m.triangles[f]) {
      if (x == v) continue;
      const tissue::EdgeRecord& r = m.edges.at(edge_key(v, x));
      for (std::uint32_t g : r.faces)
        if (g != kNoFace && g != f) stack.push_back(g);
    }
  }
  std::sort(all.begin(), all.end());
  std::uint32_t sector = 0;
  for (std::uint32_t seed : all) {
    if (std::any_of(fan.begin(), fan.end(), [&](const auto& e) { return e.first == seed; }))
      continue;
    stack = {seed};
    while (!stack.empty()) {
      const std::uint32_t f = stack.back();
      stack.pop_back();
      if (std::any_of(fan.begin(), fan.end(), [&](const auto& e) { return e.first == f; }))
        continue;
      fan.emplace_back(f, sector);
      for (std::uint32_t x : m.triangles[f]) {
        if (x == v || is_cut(edge_key(v, x))) continue;
        const tissue::EdgeRecord& r = m.edges.at(edge_key(v, x));
        for (std::uint32_t g : r.faces)
          if (g != kNoFace && g != f) stack.push_back(g);
      }
    }
    ++sector;
  }
}

// Gives every vertex on a cut edge one copy per extra sector of its fan, so the sides part.
tissue::TopologyChange separate_along_cut(tissue::TissueWorld& world, std::uint32_t mesh_index,
                                          const std::vector<std::uint64_t>& pending,
                                          FasciaCutResult& result) {
  const tissue::MeshObject& m = world.meshes[mesh_index];
  std::vector<std::uint32_t> vertices;
  for (std::uint64_t key : pending) {
    vertices.push_back(static_cast<std::uint32_t>(key >> 32));
    vertices.push_back(static_cast<std::uint32_t>(key));
  }
  std::sort(vertices.begin(), vertices.end());
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
  tissue::MeshEdit edit;
  std::vector<std::pair<std::uint32_t, Triangle>> renamed;  // (triangle, its new vertices)
  std::vector<std::pair<std::uint32_t, std::uint32_t>> fan;
  for (std::uint32_t v : vertices) {
    // A triangle at v: a face of one of its cut edges.
    std::uint32_t start = kNoFace;
    for (std::uint64_t key : pending) {
      if (static_cast<std::uint32_t>(key >> 32) == v || static_cast<std::uint32_t>(key) == v) {
        start = m.edges.at(key).faces[0];
        break;
      }
    }
    fan_sectors(m, v, start, pending, fan);
    std::uint32_t sectors = 0;
    for (const auto& e : fan)
      sectors = std::max(sectors, e.second + 1);
    for (std::uint32_t s = 1; s < sectors; ++s) {
      const std::uint32_t copy =
          m.particle_count + static_cast<std::uint32_t>(edit.vertices.size());
      edit.vertices.push_back({v, v, 0});
      for (const auto& [fan_triangle, sector] : fan) {
        if (sector != s) continue;
        const std::uint32_t f = fan_triangle;  // a structured binding cannot be captured (clang 14)
        auto it = std::find_if(renamed.begin(), renamed.end(),
                               [&](const auto& r) { return r.first == f; });
        if (it == renamed.end()) {
          renamed.emplace_back(f, m.triangles[f]);
          it = renamed.end() - 1;
        }
        for (std::uint32_t& x : it->second)
          if (x == v) x = copy;
      }
    }
  }
  std::sort(renamed.begin(), renamed.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  edit.replaced = std::move(renamed);
  result.vertices_copied = static_cast<std::uint32_t>(edit.vertices.size());
  tissue::TopologyChange change = tissue::apply_mesh_edit(world, mesh_index, edit);
  if (change.status == tissue::EditStatus::applied) {
    result.new_vertices.insert(result.new_vertices.end(), edit.vertices.begin(),
                               edit.vertices.end());
  }
  return change;
}

void add_counts(const tissue::TopologyChange& c, FasciaCutResult& r) {
  r.distance_removed += c.distance_removed.size();
  r.distance_added += c.distance_added.size();
  r.dihedral_removed += c.dihedral_removed.size();
  r.dihedral_added += c.dihedral_added.size();
}

}  // namespace

FasciaCutter make_fascia_cutter(std::uint32_t mesh) {
  FasciaCutter c;
  c.mesh = mesh;
  return c;
}

FasciaCutResult cut_fascia(tissue::TissueWorld& world, const FasciaCutParams& params,
                           const CuttingGeometry& cut, FasciaCutter& cutter) {
  FasciaCutResult result;
  result.first_new_vertex = world.meshes[cutter.mesh].particle_count;
  SweptArea area;
  if (!make_swept_area(cut, params.proximity, area)) return result;
  const tissue::MeshObject& m = world.meshes[cutter.mesh];
  Planner pl{world, m, params, area, {}, {}, {}, {}, cutter.cut_vertices};
  pl.side.assign(m.particle_count, 2);
  pl.on_cut.assign(m.particle_count, 0);
  for (std::uint32_t f = 0; f < m.triangles.size(); ++f) {
    const Triangle& t = m.triangles[f];
    Vec3 lo = pl.position(t[0]), hi = lo;
    for (std::uint32_t v : {t[1], t[2]}) {
      lo = lo.cwiseMin(pl.position(v));
      hi = hi.cwiseMax(pl.position(v));
    }
    if ((lo.array() > area.high.array()).any() || (hi.array() < area.low.array()).any()) continue;
    pl.candidates.push_back(f);
    for (std::uint32_t v : t)
      pl.classify(v);
  }
  if (pl.candidates.empty()) return result;

  std::vector<std::uint64_t> cut_edges;
  const tissue::TopologyChange split =
      split_crossed_triangles(world, pl, cutter.mesh, cut_edges, cutter.pending, result);
  add_counts(split, result);
  if (split.status != tissue::EditStatus::applied) {
    result.status = split.status;
    return result;
  }
  result.cut_edges = static_cast<std::uint32_t>(cut_edges.size());
  for (const Split& sp : pl.splits)
    if (sp.kept) cutter.cut_vertices.push_back(sp.vertex);
  for (std::uint64_t key : cut_edges) {
    cutter.cut_vertices.push_back(static_cast<std::uint32_t>(key >> 32));
    cutter.cut_vertices.push_back(static_cast<std::uint32_t>(key));
  }
  std::sort(cutter.cut_vertices.begin(), cutter.cut_vertices.end());
  cutter.cut_vertices.erase(std::unique(cutter.cut_vertices.begin(), cutter.cut_vertices.end()),
                            cutter.cut_vertices.end());
  // Cut edges join those waiting; edges already on the boundary need no separating.
  const tissue::MeshObject& after = world.meshes[cutter.mesh];
  for (std::uint64_t key : cut_edges) {
    const auto it = after.edges.find(key);
    if (it != after.edges.end() && it->second.faces[1] != kNoFace) cutter.pending.push_back(key);
  }
  std::sort(cutter.pending.begin(), cutter.pending.end());
  cutter.pending.erase(std::unique(cutter.pending.begin(), cutter.pending.end()),
                       cutter.pending.end());
  if (cutter.pending.empty()) return result;

  const tissue::TopologyChange parted =
      separate_along_cut(world, cutter.mesh, cutter.pending, result);
  add_counts(parted, result);
  if (parted.status != tissue::EditStatus::applied) {
    result.status = parted.status;
    return result;
  }
  for (std::uint32_t k = 0; k < result.vertices_copied; ++k)     // copies lie on the cut too
    cutter.cut_vertices.push_back(parted.first_new_vertex + k);  // all above the rest: sorted
  // Edges that parted are on the boundary now (or gone); the rest keep waiting.
  const tissue::MeshObject& parted_mesh = world.meshes[cutter.mesh];
  std::erase_if(cutter.pending, [&](std::uint64_t key) {
    const auto it = parted_mesh.edges.find(key);
    return it == parted_mesh.edges.end() || it->second.faces[1] == kNoFace;
  });
  return result;
}

}  // namespace imasim::surgery
