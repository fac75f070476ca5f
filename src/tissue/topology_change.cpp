#include "tissue/topology_change.hpp"

#include <algorithm>
#include <cmath>

#include "geometry/closest_point.hpp"
#include "geometry/vertex_normals.hpp"
#include "math/validation_assert.hpp"
#include "physics/membrane_material.hpp"
#include "physics/mesh_constraints.hpp"
#include "physics/validation.hpp"
#include "tissue/mesh_object.hpp"

namespace imasim::tissue {
namespace {

using geometry::kNoFace;
using geometry::Triangle;

void add_face(EdgeRecord& r, std::uint32_t face) {
  if (r.faces[0] == kNoFace) {
    r.faces[0] = face;
  } else {
    r.faces[1] = face;  // the caller keeps the mesh a manifold: at most two faces per edge
  }
}

void remove_face(EdgeRecord& r, std::uint32_t face) {
  if (r.faces[0] == face) {
    r.faces[0] = r.faces[1];
    r.faces[1] = kNoFace;
  } else if (r.faces[1] == face) {
    r.faces[1] = kNoFace;
  }
}

// The vertex of `t` that is neither a nor b.
std::uint32_t opposite_vertex(const Triangle& t, std::uint32_t a, std::uint32_t b) {
  for (std::uint32_t v : t)
    if (v != a && v != b) return v;
  return t[0];
}

// True when `t` runs from a to b (a followed by b in its winding).
bool runs_from(const Triangle& t, std::uint32_t a, std::uint32_t b) {
  for (int k = 0; k < 3; ++k)
    if (t[k] == a && t[(k + 1) % 3] == b) return true;
  return false;
}

// Barycentric coordinates of p in the triangle (x0, x1, x2), by least squares in its plane.
std::array<Real, 3> barycentric(const Vec3& p, const Vec3& x0, const Vec3& x1, const Vec3& x2) {
  const Vec3 e1 = x1 - x0, e2 = x2 - x0, d = p - x0;
  const Real a = e1.dot(e1), b = e1.dot(e2), c = e2.dot(e2);
  const Real det = a * c - b * b;
  if (!(det > 0)) return {1, 0, 0};
  const Real u = (c * e1.dot(d) - b * e2.dot(d)) / det;
  const Real v = (a * e2.dot(d) - b * e1.dot(d)) / det;
  return {1 - u - v, u, v};
}

Vec3 rest_vertex(const TissueWorld& w, const MeshObject& m, std::uint32_t v) {
  return w.state.particles.rest_position[m.first_particle + v];
}

// Re-binds the bindings whose triangle was replaced to the piece (the replaced triangle's new
// version or a triangle added from it) that holds their rest point.
void rebind(std::vector<geometry::SurfaceBinding>& bindings, std::vector<std::uint32_t>* faces,
            const TissueWorld& w, const MeshObject& m, const std::vector<Triangle>& old_triangles,
            const std::vector<std::uint32_t>& replaced_slot, const MeshEdit& edit,
            std::uint32_t first_added) {
  for (std::size_t k = 0; k < bindings.size(); ++k) {
    geometry::SurfaceBinding& b = bindings[k];
    if (b.triangle >= replaced_slot.size() || replaced_slot[b.triangle] == kNoFace) continue;
    const Triangle& old = old_triangles[replaced_slot[b.triangle]];
    const Vec3 p = b.bary[0] * rest_vertex(w, m, old[0]) + b.bary[1] * rest_vertex(w, m, old[1]) +
                   b.bary[2] * rest_vertex(w, m, old[2]);
    std::uint32_t best = b.triangle;
    std::array<Real, 3> best_bary = {1, 0, 0};
    Real best_score = -std::numeric_limits<Real>::infinity();
    auto consider = [&](std::uint32_t f) {
      const Triangle& t = m.triangles[f];
      const auto bary =
          barycentric(p, rest_vertex(w, m, t[0]), rest_vertex(w, m, t[1]), rest_vertex(w, m, t[2]));
      const Real score = std::min({bary[0], bary[1], bary[2]});
      if (score > best_score) {
        best_score = score;
        best = f;
        best_bary = bary;
      }
    };
    const std::uint32_t origin = b.triangle;
    consider(origin);
    for (std::size_t a = 0; a < edit.added.size(); ++a) {
      if (edit.added[a].origin == origin) consider(first_added + static_cast<std::uint32_t>(a));
    }
    b.triangle = best;
    b.bary = best_bary;
    if (faces) (*faces)[k] = best;
  }
}

// Coupling pairs whose source vertex was copied follow the copy whose triangles' rest centroids
// lie nearest the destination's rest position (the side of the cut it is on).
void follow_copies(TissueWorld& w, const MeshObject& m, const MeshEdit& edit,
                   std::uint32_t first_new) {
  std::vector<std::uint32_t> family(m.particle_count, kNoFace);  // original of each copy family
  bool any = false;
  for (std::size_t k = 0; k < edit.vertices.size(); ++k) {
    const NewVertex& nv = edit.vertices[k];
    if (nv.a != nv.b) continue;
    family[nv.a] = nv.a;
    family[first_new + k] = nv.a;
    any = true;
  }
  if (!any) return;
  // Rest centroids of the triangles around each member of a family.
  std::vector<std::pair<std::uint32_t, Vec3>> around;  // (member vertex, centroid)
  for (const Triangle& t : m.triangles) {
    const Vec3 c =
        (rest_vertex(w, m, t[0]) + rest_vertex(w, m, t[1]) + rest_vertex(w, m, t[2])) / Real(3);
    for (std::uint32_t v : t)
      if (family[v] != kNoFace) around.emplace_back(v, c);
  }
  const physics::Particles& P = w.state.particles;
  for (OffsetCoupling& c : w.couplings) {
    for (auto& [source, destination] : c.pairs) {
      if (source < m.first_particle || source >= m.first_particle + m.particle_count) continue;
      const std::uint32_t v = source - m.first_particle;
      if (family[v] == kNoFace) continue;
      Real best = std::numeric_limits<Real>::infinity();
      for (const auto& [member, centroid] : around) {
        if (family[member] != family[v]) continue;
        const Real d2 = (centroid - P.rest_position[destination]).squaredNorm();
        if (d2 < best) {
          best = d2;
          source = m.first_particle + member;
        }
      }
    }
  }
}

std::string edit_problem(const MeshObject& m, const MeshEdit& edit) {
  const std::size_t n_old = m.particle_count, n_new = n_old + edit.vertices.size();
  for (const NewVertex& v : edit.vertices) {
    if (v.a >= n_old || v.b >= n_old) return "a new vertex's parent does not exist";
    if (!(v.t >= 0 && v.t <= 1)) return "a new vertex's weight is outside [0, 1]";
  }
  auto bad_triangle = [&](const Triangle& t) {
    return t[0] >= n_new || t[1] >= n_new || t[2] >= n_new || t[0] == t[1] || t[1] == t[2] ||
           t[0] == t[2];
  };
  for (const auto& [f, t] : edit.replaced) {
    if (f >= m.triangles.size() || bad_triangle(t)) return "a replaced triangle is invalid";
  }
  for (const MeshEdit::Added& a : edit.added) {
    if (a.origin >= m.triangles.size() || bad_triangle(a.triangle)) {
      return "an added triangle is invalid";
    }
  }
  return "";
}

// Removes the constraints of the edges `touched` (sorted keys) and clears them in the index.
void remove_edge_constraints(TissueWorld& w, MeshObject& m,
                             const std::vector<std::uint64_t>& touched, TopologyChange& change) {
  auto& cs = w.state.constraints;
  for (std::uint64_t key : touched) {
    const auto it = m.edges.find(key);
    if (it == m.edges.end()) continue;
    // Every edge has its row, unless another solver took them (implicit fascia).
    IMASIM_ASSERT(!m.rows_in_xpbd || cs.distance.resolves(it->second.distance));
    if (cs.distance.remove(it->second.distance))
      change.distance_removed.push_back(it->second.distance);
    if (cs.dihedral.remove(it->second.dihedral))
      change.dihedral_removed.push_back(it->second.dihedral);
    it->second.distance = {};
    it->second.dihedral = {};
  }
}

// Gives each edge of `touched` (sorted keys) that still has a face the constraints the mesh
// needs now (eq. 2 on every edge, eq. 3 on interior ones) and drops those left without a face.
void add_edge_constraints(TissueWorld& w, MeshObject& m, const std::vector<std::uint64_t>& touched,
                          TopologyChange& change) {
  physics::Particles& P = w.state.particles;
  auto& cs = w.state.constraints;
  const std::uint32_t first = m.first_particle;
  for (std::uint64_t key : touched) {
    const auto it = m.edges.find(key);
    if (it == m.edges.end()) continue;
    EdgeRecord& r = it->second;
    if (r.faces[0] == kNoFace) {
      m.edges.erase(it);
      continue;
    }
    const Triangle& f0 = m.triangles[r.faces[0]];
    auto a = static_cast<std::uint32_t>(key >> 32), b = static_cast<std::uint32_t>(key);
    if (!runs_from(f0, a, b)) std::swap(a, b);  // f0 runs a -> b: its wing is p0 (eq. 3)
    // Membrane rows take their compliance scale from the new rest geometry.
    const bool membrane = m.per_row == physics::CompliancePerRow::membrane;
    const Real length2 = (P.rest_position[first + a] - P.rest_position[first + b]).squaredNorm();
    Real area = physics::rest_triangle_area(P, first, f0);
    if (r.faces[1] != kNoFace)
      area += physics::rest_triangle_area(P, first, m.triangles[r.faces[1]]);
    r.distance = physics::add_distance(
        cs, P, first + a, first + b, m.stretch_material,
        membrane ? physics::stretch_compliance_scale(length2, area) : Real(1));
    change.distance_added.push_back(r.distance);
    if (r.faces[1] != kNoFace) {
      const Triangle& f1 = m.triangles[r.faces[1]];
      r.dihedral = physics::add_dihedral(
          cs, P, first + opposite_vertex(f0, a, b), first + opposite_vertex(f1, a, b), first + a,
          first + b, m.bend_material,
          membrane ? physics::bend_compliance_scale(length2, area) : Real(1));
      change.dihedral_added.push_back(r.dihedral);
    }
  }
}

}  // namespace

geometry::TriangleMesh rest_mesh(const TissueWorld& w, const MeshObject& m) {
  geometry::TriangleMesh mesh;
  const auto& rest = w.state.particles.rest_position;
  mesh.vertices.assign(rest.begin() + m.first_particle,
                       rest.begin() + m.first_particle + m.particle_count);
  mesh.triangles = m.triangles;
  return mesh;
}

void index_mesh_edges(TissueWorld& w, std::uint32_t mesh) {
  MeshObject& m = w.meshes[mesh];
  m.edges.clear();
  for (std::uint32_t f = 0; f < m.triangles.size(); ++f) {
    const Triangle& t = m.triangles[f];
    for (int k = 0; k < 3; ++k)
      add_face(m.edges[edge_key(t[k], t[(k + 1) % 3])], f);
  }
  const std::uint32_t lo = m.first_particle, hi = m.first_particle + m.particle_count;
  auto inside = [&](std::uint32_t p) { return p >= lo && p < hi; };
  auto& cs = w.state.constraints;
  for (const auto& g : cs.distance.groups()) {
    for (const physics::DistanceRow& r : g.rows) {
      if (!inside(r.i) || !inside(r.j)) continue;
      const auto it = m.edges.find(edge_key(r.i - lo, r.j - lo));
      if (it != m.edges.end()) it->second.distance = cs.distance.handle_of(r);
    }
  }
  for (const auto& g : cs.dihedral.groups()) {
    for (const physics::DihedralRow& r : g.rows) {
      if (!inside(r.p[2]) || !inside(r.p[3])) continue;
      const auto it = m.edges.find(edge_key(r.p[2] - lo, r.p[3] - lo));
      if (it != m.edges.end()) it->second.dihedral = cs.dihedral.handle_of(r);
    }
  }
}

TopologyChange apply_mesh_edit(TissueWorld& w, std::uint32_t mesh, const MeshEdit& edit) {
  TopologyChange change;
  MeshObject& m = w.meshes[mesh];
  change.first_new_vertex = m.particle_count;
  if (std::string why = edit_problem(m, edit); !why.empty()) {
    change.status = EditStatus::invalid;
    change.message = m.name + ": " + why;
    return change;
  }
  if (m.particle_count + edit.vertices.size() > m.particle_capacity) {
    change.status = EditStatus::out_of_capacity;
    change.message = m.name + ": no spare vertices left for the cut";
    return change;
  }
  if (edit.empty()) return change;
  physics::Particles& P = w.state.particles;
  const std::uint32_t first = m.first_particle, n_old = m.particle_count;
  const auto n_new = static_cast<std::uint32_t>(n_old + edit.vertices.size());

  // Edges the change touches: those of the replaced triangles, before and after, and of the
  // added ones. Sorted, so constraints are rebuilt in a fixed order (determinism).
  std::vector<std::uint64_t> touched;
  auto touch = [&](const Triangle& t) {
    for (int k = 0; k < 3; ++k)
      touched.push_back(edge_key(t[k], t[(k + 1) % 3]));
  };
  for (const auto& [f, t] : edit.replaced) {
    touch(m.triangles[f]);
    touch(t);
  }
  for (const MeshEdit::Added& a : edit.added)
    touch(a.triangle);
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());

  remove_edge_constraints(w, m, touched, change);

  // New particles, interpolated from their parents.
  for (std::uint32_t k = 0; k < edit.vertices.size(); ++k) {
    const NewVertex& nv = edit.vertices[k];
    IMASIM_ASSERT(nv.a < n_old + k && nv.b < n_old + k && nv.t >= 0 && nv.t <= 1);
    const std::uint32_t a = first + nv.a, b = first + nv.b, i = first + n_old + k;
    const Real s = 1 - nv.t, t = nv.t;
    P.position[i] = s * P.position[a] + t * P.position[b];
    P.predicted[i] = P.position[i];
    P.rest_position[i] = s * P.rest_position[a] + t * P.rest_position[b];
    P.velocity[i] = s * P.velocity[a] + t * P.velocity[b];
    P.inverse_mass[i] = P.is_fixed(a) && P.is_fixed(b) ? Real(0) : Real(1);  // mass set below
    if (w.reference.size() == P.size()) w.reference[i] = s * w.reference[a] + t * w.reference[b];
  }
  m.particle_count = n_new;

  // Triangles, and the faces in the edge index.
  std::vector<Triangle> old_triangles;
  std::vector<std::uint32_t> replaced_slot(m.triangles.size(), kNoFace);
  for (const auto& [f, t] : edit.replaced) {
    const Triangle& old = m.triangles[f];
    for (int k = 0; k < 3; ++k) {
      const auto it = m.edges.find(edge_key(old[k], old[(k + 1) % 3]));
      if (it != m.edges.end()) remove_face(it->second, f);
    }
    replaced_slot[f] = static_cast<std::uint32_t>(old_triangles.size());
    old_triangles.push_back(old);
    m.triangles[f] = t;
  }
  const auto first_added = static_cast<std::uint32_t>(m.triangles.size());
  for (const MeshEdit::Added& a : edit.added)
    m.triangles.push_back(a.triangle);
  for (const auto& [f, t] : edit.replaced) {
    for (int k = 0; k < 3; ++k)
      add_face(m.edges[edge_key(t[k], t[(k + 1) % 3])], f);
  }
  for (std::uint32_t f = first_added; f < m.triangles.size(); ++f) {
    const Triangle& t = m.triangles[f];
    for (int k = 0; k < 3; ++k)
      add_face(m.edges[edge_key(t[k], t[(k + 1) % 3])], f);
  }

  // eq. 5 for the new vertex count: the object's mass stays M_total.
  const Real inverse_vertex_mass = Real(n_new) / m.total_mass;
  for (std::uint32_t v = 0; v < n_new; ++v) {
    if (!P.is_fixed(first + v)) P.inverse_mass[first + v] = inverse_vertex_mass;
  }

  add_edge_constraints(w, m, touched, change);

  // Mappings onto the mesh.
  for (StrandSet& s : w.strands) {
    if (s.mesh_a == mesh)
      rebind(s.end_a, &s.face_a, w, m, old_triangles, replaced_slot, edit, first_added);
    if (s.mesh_b == mesh)
      rebind(s.end_b, nullptr, w, m, old_triangles, replaced_slot, edit, first_added);
  }
  for (VisualMesh& v : w.visuals) {
    if (v.source_mesh == mesh) {
      rebind(v.bindings, nullptr, w, m, old_triangles, replaced_slot, edit, first_added);
    }
  }
  follow_copies(w, m, edit, n_old);

  m.normals.resize(n_new);
  geometry::compute_vertex_normals(mesh_positions(w, m), m.triangles, m.normals);
  ++m.topology_revision;
  return change;
}

TopologyChange remove_mesh_triangles(TissueWorld& w, std::uint32_t mesh,
                                     std::span<const std::uint32_t> triangles) {
  TopologyChange change;
  MeshObject& m = w.meshes[mesh];
  change.first_new_vertex = m.particle_count;
  const auto face_count = static_cast<std::uint32_t>(m.triangles.size());
  std::vector<std::uint8_t> gone(face_count, 0);
  for (std::uint32_t f : triangles) {
    if (f >= face_count) {
      change.status = EditStatus::invalid;
      change.message = m.name + ": a removed triangle does not exist";
      return change;
    }
    gone[f] = 1;
  }
  const auto removed = static_cast<std::uint32_t>(std::count(gone.begin(), gone.end(), 1));
  if (removed == 0) return change;
  if (removed == face_count) {
    change.status = EditStatus::invalid;
    change.message = m.name + ": removing every triangle";
    return change;
  }
  physics::Particles& P = w.state.particles;
  const std::uint32_t first = m.first_particle;
  // Vertices left in no triangle are retired: none may be held or be a coupling's destination.
  std::vector<std::uint8_t> used(m.particle_count, 0);
  for (std::uint32_t f = 0; f < face_count; ++f) {
    if (!gone[f])
      for (std::uint32_t v : m.triangles[f])
        used[v] = 1;
  }
  auto retiring = [&](std::uint32_t particle) {
    return particle >= first && particle < first + m.particle_count && !used[particle - first];
  };
  for (std::uint32_t v = 0; v < m.particle_count; ++v) {
    if (!used[v] && first + v < w.held.size() && w.held[first + v]) {
      change.status = EditStatus::invalid;
      change.message = m.name + ": a removed vertex is held by an instrument";
      return change;
    }
  }
  for (const OffsetCoupling& c : w.couplings) {
    if (c.beta == Beta::manipulated) continue;  // only while held fat drives it: let go below
    for (const auto& pair : c.pairs) {
      if (retiring(pair.second)) {
        change.status = EditStatus::invalid;
        change.message = m.name + ": a removed vertex is moved by coupling " + c.name;
        return change;
      }
    }
  }

  // The removed triangles' edges lose their constraints and those faces.
  std::vector<std::uint64_t> touched;
  for (std::uint32_t f = 0; f < face_count; ++f) {
    if (!gone[f]) continue;
    const Triangle& t = m.triangles[f];
    for (int k = 0; k < 3; ++k)
      touched.push_back(edge_key(t[k], t[(k + 1) % 3]));
  }
  std::sort(touched.begin(), touched.end());
  touched.erase(std::unique(touched.begin(), touched.end()), touched.end());
  remove_edge_constraints(w, m, touched, change);
  for (std::uint32_t f = 0; f < face_count; ++f) {
    if (!gone[f]) continue;
    const Triangle& t = m.triangles[f];
    for (int k = 0; k < 3; ++k)
      remove_face(m.edges[edge_key(t[k], t[(k + 1) % 3])], f);
  }

  // Bindings on a removed triangle move to the surviving triangle nearest their point now: the
  // piece was freed where it lies, beside the sheet's edge it parted from (at rest the nearest
  // triangle could be across the cut, on a flap held far away). The binding's new barycentric
  // coordinates are those of that nearest point.
  const std::vector<Triangle> before = m.triangles;
  auto rehome = [&](geometry::SurfaceBinding& b) {
    if (b.triangle >= face_count || !gone[b.triangle]) return;
    const Triangle& old = before[b.triangle];
    auto now = [&](std::uint32_t v) { return P.position[first + v]; };
    const Vec3 p = b.bary[0] * now(old[0]) + b.bary[1] * now(old[1]) + b.bary[2] * now(old[2]);
    Real best = std::numeric_limits<Real>::infinity();
    for (std::uint32_t f = 0; f < face_count; ++f) {
      if (gone[f]) continue;
      const Triangle& t = before[f];
      const geometry::TrianglePoint q =
          geometry::closest_point_on_triangle(p, now(t[0]), now(t[1]), now(t[2]));
      if (q.distance2 < best) {
        best = q.distance2;
        b.triangle = f;
        b.bary = q.bary;
      }
    }
  };

  // The survivors keep their order; every index to a triangle is renumbered.
  std::vector<std::uint32_t> renumber(face_count, kNoFace);
  std::uint32_t next = 0;
  for (std::uint32_t f = 0; f < face_count; ++f) {
    if (gone[f]) continue;
    renumber[f] = next;
    m.triangles[next++] = before[f];
  }
  m.triangles.resize(next);
  for (auto& [key, r] : m.edges) {
    for (std::uint32_t& face : r.faces)
      if (face != kNoFace) face = renumber[face];
  }
  auto renumber_bindings = [&](std::vector<geometry::SurfaceBinding>& bindings,
                               std::vector<std::uint32_t>* faces) {
    for (std::size_t k = 0; k < bindings.size(); ++k) {
      rehome(bindings[k]);
      if (bindings[k].triangle < face_count) bindings[k].triangle = renumber[bindings[k].triangle];
      if (faces) (*faces)[k] = bindings[k].triangle;
    }
  };
  for (StrandSet& s : w.strands) {
    if (s.mesh_a == mesh) renumber_bindings(s.end_a, &s.face_a);
    if (s.mesh_b == mesh) renumber_bindings(s.end_b, nullptr);
  }
  for (VisualMesh& v : w.visuals)
    if (v.source_mesh == mesh) renumber_bindings(v.bindings, nullptr);

  // Retired vertices: fixed where they are, at rest (eq. 5's share of a vertex leaves with
  // them: the others keep M_total / n).
  for (std::uint32_t v = 0; v < m.particle_count; ++v) {
    if (used[v]) continue;
    const std::uint32_t i = first + v;
    P.inverse_mass[i] = 0;
    P.velocity[i] = Vec3::Zero();
    P.predicted[i] = P.position[i];
  }
  // What a retired vertex drove through a coupling is no longer driven by it, and a retired
  // vertex that held fat would drive (beta by manipulation) is driven no more.
  for (OffsetCoupling& c : w.couplings) {
    const bool let_go = c.beta == Beta::manipulated;
    std::erase_if(c.pairs, [&](const auto& pair) {
      return retiring(pair.first) || (let_go && retiring(pair.second));
    });
  }
  add_edge_constraints(w, m, touched, change);
  geometry::compute_vertex_normals(mesh_positions(w, m), m.triangles, m.normals);
  ++m.topology_revision;
  return change;
}

std::string first_topology_defect(TissueWorld& w, std::uint32_t mesh,
                                  const geometry::MeshCheckOptions& options) {
  const MeshObject& m = w.meshes[mesh];
  const std::string where = m.name + ": ";
  const geometry::TriangleMesh rest = rest_mesh(w, m);
  geometry::MeshCheckOptions checks = options;
  // Vertices in no triangle are retired ones (remove_mesh_triangles), checked below.
  checks.require_used_vertices = false;
  if (std::string d = geometry::first_mesh_defect(rest, checks); !d.empty()) return where + d;
  std::vector<std::uint8_t> used(m.particle_count, 0);
  for (const Triangle& t : m.triangles)
    for (std::uint32_t v : t)
      used[v] = 1;
  for (std::uint32_t v = 0; v < m.particle_count; ++v) {
    const std::uint32_t i = m.first_particle + v;
    const physics::Particles& P = w.state.particles;
    if (!used[v] && options.require_used_vertices &&
        (!P.is_fixed(i) || P.velocity[i] != Vec3::Zero()))
      return where + "vertex " + std::to_string(v) + " is in no triangle but not retired";
  }

  // The edge index and the constraints on each edge.
  const geometry::EdgeAdjacency adjacency = geometry::build_edge_adjacency(rest);
  if (adjacency.edges.size() != m.edges.size()) {
    return where + "the edge index has " + std::to_string(m.edges.size()) + " edges, the mesh " +
           std::to_string(adjacency.edges.size());
  }
  const auto& cs = w.state.constraints;
  const std::uint32_t first = m.first_particle;
  for (const geometry::MeshEdge& e : adjacency.edges) {
    const std::string edge = "edge (" + std::to_string(e.a) + ", " + std::to_string(e.b) + ")";
    const auto it = m.edges.find(edge_key(e.a, e.b));
    if (it == m.edges.end()) return where + edge + " is missing from the edge index";
    const EdgeRecord& r = it->second;
    const bool same_faces = (r.faces[0] == e.faces[0] && r.faces[1] == e.faces[1]) ||
                            (r.faces[0] == e.faces[1] && r.faces[1] == e.faces[0]);
    if (!same_faces) return where + edge + " has the wrong faces in the edge index";
    const physics::DistanceRow* d = cs.distance.find(r.distance);
    if (!d || edge_key(d->i - first, d->j - first) != edge_key(e.a, e.b)) {
      return where + edge + " has no distance constraint";
    }
    const physics::DihedralRow* h = cs.dihedral.find(r.dihedral);
    if (e.is_interior()) {
      // Either face may be the first: (w0, w1, a, b) and (w1, w0, b, a) are one constraint.
      const std::array<std::uint32_t, 4> forward = {first + e.opposite[0], first + e.opposite[1],
                                                    first + e.a, first + e.b};
      const std::array<std::uint32_t, 4> backward = {forward[1], forward[0], forward[3],
                                                     forward[2]};
      if (!h || (h->p != forward && h->p != backward)) {
        return where + "interior " + edge + " has no dihedral constraint on its faces";
      }
    } else if (h) {
      return where + "boundary " + edge + " has a dihedral constraint";
    }
  }
  // No constraint on the object beyond those of its edges, none on an unused particle.
  const std::uint32_t live_end = first + m.particle_count, end = first + m.particle_capacity;
  std::size_t on_mesh = 0;
  for (const auto& g : cs.distance.groups()) {
    for (const physics::DistanceRow& r : g.rows) {
      const bool in_i = r.i >= first && r.i < end, in_j = r.j >= first && r.j < end;
      if ((in_i && r.i >= live_end) || (in_j && r.j >= live_end)) {
        return where + "a distance constraint refers to an unused particle";
      }
      on_mesh += in_i && in_j ? 1 : 0;
    }
  }
  if (on_mesh != adjacency.edges.size()) {
    return where + std::to_string(on_mesh) + " distance constraints for " +
           std::to_string(adjacency.edges.size()) + " edges";
  }
  auto unused = [&](std::uint32_t p) {
    return (p >= live_end && p < end) || (p >= first && p < live_end && !used[p - first]);
  };
  for (const auto& g : cs.dihedral.groups()) {
    for (const physics::DihedralRow& r : g.rows) {
      for (std::uint32_t p : r.p)
        if (unused(p)) return where + "a dihedral constraint refers to an unused particle";
    }
  }
  for (const auto& g : cs.attachment.groups()) {
    for (const physics::AttachmentRow& r : g.rows) {
      for (std::uint32_t p : r.particles())
        if (unused(p)) return where + "an attachment refers to an unused particle";
    }
  }
  for (const OffsetCoupling& c : w.couplings) {
    for (const auto& [s, d] : c.pairs) {
      if (unused(s) || unused(d))
        return where + "coupling " + c.name + " refers to an unused particle";
    }
  }
  auto check_bindings = [&](const std::vector<geometry::SurfaceBinding>& bindings,
                            const std::string& what) -> std::string {
    for (const geometry::SurfaceBinding& b : bindings) {
      if (b.triangle >= m.triangles.size()) return where + what + " is bound to a missing triangle";
      const Real sum = b.bary[0] + b.bary[1] + b.bary[2];
      if (!std::isfinite(sum) || std::abs(sum - 1) > Real(1e-9)) {
        return where + what + " has barycentric coordinates that do not sum to 1";
      }
    }
    return "";
  };
  for (const StrandSet& s : w.strands) {
    if (s.mesh_a == mesh) {
      if (std::string d = check_bindings(s.end_a, s.name + " end"); !d.empty()) return d;
    }
    if (s.mesh_b == mesh) {
      if (std::string d = check_bindings(s.end_b, s.name + " end"); !d.empty()) return d;
    }
  }
  // eq. 5 and finite values.
  const physics::Particles& P = w.state.particles;
  const Real expected = Real(m.particle_count) / m.total_mass;
  for (std::uint32_t i = first; i < live_end; ++i) {
    if (!P.position[i].allFinite() || !P.velocity[i].allFinite() ||
        !P.rest_position[i].allFinite()) {
      return where + "particle " + std::to_string(i) + " is not finite";
    }
    if (!P.is_fixed(i) && std::abs(P.inverse_mass[i] - expected) > Real(1e-12) * expected) {
      return where + "particle " + std::to_string(i) + " does not carry M_total / n (eq. 5)";
    }
  }
  return physics::validate_state(w.model, w.state);
}

}  // namespace imasim::tissue
