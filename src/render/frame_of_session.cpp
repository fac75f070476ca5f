#include "render/frame_of_session.hpp"

#include <algorithm>
#include <cmath>

namespace imasim::render {

namespace {

// A coagulated particle is drawn fully shaded; heated tissue darkens as it nears the
// coagulation rise (unit: K), so the operator sees the heat spread before the tissue turns.
constexpr float kShadeRise = 40.0f;

Surface& next_surface(RenderFrame& out, std::size_t& used, Look look) {
  if (used == out.surfaces.size()) out.surfaces.emplace_back();
  Surface& s = out.surfaces[used++];
  s.clear();
  s.look = look;
  return s;
}

void push(std::vector<float>& v, const Vec3& x) {
  v.push_back(float(x.x())), v.push_back(float(x.y())), v.push_back(float(x.z()));
}

// Area-weighted vertex normals of s's triangles, in float.
void compute_normals(Surface& s) {
  s.normals.assign(s.positions.size(), 0.0f);
  const float* p = s.positions.data();
  for (std::size_t t = 0; t + 2 < s.indices.size(); t += 3) {
    const std::uint32_t a = s.indices[t], b = s.indices[t + 1], c = s.indices[t + 2];
    const float e1[3] = {p[3 * b] - p[3 * a], p[3 * b + 1] - p[3 * a + 1],
                         p[3 * b + 2] - p[3 * a + 2]};
    const float e2[3] = {p[3 * c] - p[3 * a], p[3 * c + 1] - p[3 * a + 1],
                         p[3 * c + 2] - p[3 * a + 2]};
    const float n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                        e1[0] * e2[1] - e1[1] * e2[0]};
    for (const std::uint32_t v : {a, b, c})
      for (int k = 0; k < 3; ++k)
        s.normals[3 * v + k] += n[k];
  }
  for (std::size_t v = 0; v + 2 < s.normals.size(); v += 3) {
    float* n = &s.normals[v];
    const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (len > 0) n[0] /= len, n[1] /= len, n[2] /= len;
  }
}

float shade_of(const surgery::CauteryState& c, std::uint32_t particle) {
  if (particle < c.coagulated.size() && c.coagulated[particle]) return 1.0f;
  if (particle < c.rise.size()) return std::clamp(float(c.rise[particle]) / kShadeRise, 0.0f, 0.9f);
  return 0.0f;
}

// A simulated mesh: its used vertices, its triangles, the session's vertex normals.
void add_mesh(RenderFrame& out, std::size_t& used, Look look, const tissue::MeshObject& mesh,
              const physics::Particles& particles, const surgery::CauteryState& cautery) {
  Surface& s = next_surface(out, used, look);
  // Vertices a cut added live above particle_count, up to the mesh's capacity.
  const std::uint32_t count = std::max(mesh.particle_count, mesh.particle_capacity);
  for (std::uint32_t v = 0; v < count && mesh.first_particle + v < particles.position.size(); ++v) {
    const std::uint32_t i = mesh.first_particle + v;
    push(s.positions, particles.position[i]);
    s.shade.push_back(shade_of(cautery, i));
  }
  for (const geometry::Triangle& t : mesh.triangles)
    for (const std::uint32_t v : t)
      s.indices.push_back(v);
  compute_normals(s);
}

void add_triangle_mesh(RenderFrame& out, std::size_t& used, Look look,
                       const std::vector<Vec3>& positions,
                       const std::vector<geometry::Triangle>& triangles) {
  Surface& s = next_surface(out, used, look);
  for (const Vec3& x : positions)
    push(s.positions, x);
  s.shade.assign(positions.size(), 0.0f);
  for (const geometry::Triangle& t : triangles)
    for (const std::uint32_t v : t)
      s.indices.push_back(v);
  compute_normals(s);
}

// A capsule as a closed cylinder with `sides` faces; a box as 6 faces with their own normals.
void add_cylinder(Surface& s, const Vec3& a, const Vec3& b, Real radius) {
  constexpr int sides = 14;
  const Vec3 axis = (b - a).normalized();
  const Vec3 u = axis.unitOrthogonal(), w = axis.cross(u);
  const std::uint32_t base = std::uint32_t(s.vertex_count());
  for (int k = 0; k < sides; ++k) {
    const Real angle = Real(2 * M_PI) * Real(k) / sides;
    const Vec3 radial = std::cos(angle) * u + std::sin(angle) * w;
    push(s.positions, a + radius * radial), push(s.normals, radial);
    push(s.positions, b + radius * radial), push(s.normals, radial);
    s.shade.push_back(0), s.shade.push_back(0);
  }
  for (std::uint32_t k = 0; k < sides; ++k) {
    const std::uint32_t i0 = base + 2 * k, i1 = base + 2 * ((k + 1) % sides);
    for (const std::uint32_t v : {i0, i1, i0 + 1, i0 + 1, i1, i1 + 1})
      s.indices.push_back(v);
  }
  const std::array<std::pair<Vec3, Vec3>, 2> caps = {std::pair<Vec3, Vec3>{a, -axis}, {b, axis}};
  for (const auto& [centre, n] : caps) {
    const std::uint32_t c = std::uint32_t(s.vertex_count());
    push(s.positions, centre), push(s.normals, n), s.shade.push_back(0);
    for (int k = 0; k < sides; ++k) {
      const Real angle = Real(2 * M_PI) * Real(k) / sides;
      push(s.positions, centre + radius * (std::cos(angle) * u + std::sin(angle) * w));
      push(s.normals, n), s.shade.push_back(0);
    }
    for (std::uint32_t k = 0; k < sides; ++k) {
      const std::uint32_t p = c + 1 + k, q = c + 1 + (k + 1) % sides;
      if (n.dot(axis) > 0) {
        for (const std::uint32_t v : {c, p, q})
          s.indices.push_back(v);
      } else {
        for (const std::uint32_t v : {c, q, p})
          s.indices.push_back(v);
      }
    }
  }
}

void add_box(Surface& s, const surgery::OrientedBox& box) {
  const Mat3& R = box.pose.rotation;
  for (int axis = 0; axis < 3; ++axis)
    for (const Real sign : {Real(-1), Real(1)}) {
      const Vec3 n = sign * R.col(axis);
      const Vec3 centre = box.pose.translation + box.half_extents[axis] * n;
      const int i = (axis + 1) % 3, j = (axis + 2) % 3;
      const Vec3 du = box.half_extents[i] * R.col(i), dv = box.half_extents[j] * R.col(j);
      const std::uint32_t base = std::uint32_t(s.vertex_count());
      const std::array<Vec3, 4> corners = {Vec3(centre - du - dv), Vec3(centre + du - dv),
                                           Vec3(centre + du + dv), Vec3(centre - du + dv)};
      for (const Vec3& corner : corners)
        push(s.positions, corner), push(s.normals, n), s.shade.push_back(0);
      // Counter-clockwise seen from outside: (du x dv) is along R.col(axis).
      if (sign > 0) {
        for (const std::uint32_t v : {0u, 1u, 2u, 0u, 2u, 3u})
          s.indices.push_back(base + v);
      } else {
        for (const std::uint32_t v : {0u, 2u, 1u, 0u, 3u, 2u})
          s.indices.push_back(base + v);
      }
    }
}

Look bone_look(scene::BoneKind kind) {
  return kind == scene::BoneKind::costal_cartilage ? Look::cartilage : Look::bone;
}

Matrix4 to_matrix4(const surgery::Mat4& m) {
  Matrix4 out{};
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r)
      out[c * 4 + r] = float(m(r, c));
  return out;
}

}  // namespace

void frame_of_session(const session::SurgicalSession& session, RenderFrame& out) {
  const tissue::ThoracicPatch& patch = session.scene.patch;
  const tissue::TissueWorld& world = patch.world;
  const physics::Particles& particles = world.state.particles;
  const surgery::CauteryState& cautery = session.cautery;
  std::size_t used = 0;
  out.time_s = world.state.time;

  add_mesh(out, used, Look::chest_wall, world.meshes[patch.wall], particles, cautery);
  add_mesh(out, used, Look::fascia, world.meshes[patch.fascia], particles, cautery);

  // The IMA's fine mesh; its shade from the coarse triangle each fine vertex is bound to.
  const tissue::VisualMesh& ima = world.visuals[patch.ima_visual];
  const tissue::MeshObject& ima_coarse = world.meshes[ima.source_mesh];
  {
    Surface& s = next_surface(out, used, Look::ima);
    for (std::size_t v = 0; v < ima.positions.size(); ++v) {
      push(s.positions, ima.positions[v]);
      const geometry::SurfaceBinding& b = ima.bindings[v];
      float shade = 0;
      if (b.triangle < ima_coarse.triangles.size())
        for (int k = 0; k < 3; ++k)
          shade += float(b.bary[std::size_t(k)]) *
                   shade_of(cautery, ima_coarse.first_particle +
                                         ima_coarse.triangles[b.triangle][std::size_t(k)]);
      s.shade.push_back(std::clamp(shade, 0.0f, 1.0f));
    }
    for (const geometry::Triangle& t : ima.triangles)
      for (const std::uint32_t v : t)
        s.indices.push_back(v);
    compute_normals(s);
  }

  add_triangle_mesh(out, used, Look::heart, session.scene.heart.current,
                    session.scene.heart.model.topology.triangles);
  for (const scene::DisplayMesh& bone : session.scene.skeleton)
    add_triangle_mesh(out, used, bone_look(bone.kind), bone.mesh.vertices, bone.mesh.triangles);

  // Instruments: shafts and jaws, then the hook's electrode.
  {
    Surface& s = next_surface(out, used, Look::instrument);
    // From the instruments' own state: the step's copy (station.geometry) is made only as a
    // step begins, so a session not yet stepped has none.
    surgery::ToolGeometry tool;
    for (const session::Station& station : session.stations) {
      surgery::make_tool_geometry(station.instrument, station.state, tool);
      for (const surgery::Capsule& c : tool.capsules)
        if ((c.b - c.a).norm() > 0) add_cylinder(s, c.a, c.b, c.radius);
      for (const surgery::OrientedBox& box : tool.boxes)
        add_box(s, box);
    }
  }
  const std::array<Vec3, 2> wire = session::electrode(session);
  {
    Surface& s = next_surface(out, used, Look::electrode);
    add_cylinder(s, wire[0], wire[1], session.params.electrode_radius);
  }
  out.surfaces.resize(used);

  // The fat: every live strand particle as a sphere of its drawn diameter.
  out.fat.centres.clear(), out.fat.radii.clear();
  for (const tissue::StrandSet& set : world.strands)
    for (std::uint32_t k = 0; k < set.particle_count(); ++k) {
      if (!(set.diameter[k] > 0)) continue;
      push(out.fat.centres, particles.position[set.first_particle + k]);
      out.fat.radii.push_back(float(set.diameter[k] / 2));
    }

  const session::Station& hook = session.stations[1];
  out.glow = hook.pedal != surgery::PedalMode::off && hook.power_w > 0;
  const Vec3 tip = wire[1];
  out.glow_position = {float(tip.x()), float(tip.y()), float(tip.z())};
  out.glow_strength = out.glow ? float(std::clamp(hook.power_w / 50.0, 0.2, 1.0)) : 0.0f;

  out.endoscope.view = to_matrix4(session.camera.view);
  out.endoscope.projection = to_matrix4(session.camera.projection);
  out.endoscope.eye = {float(session.camera.eye.x()), float(session.camera.eye.y()),
                       float(session.camera.eye.z())};

  // The tissue's bounds: the chest wall's (it stays in place; fascia cut free may fall away).
  const Surface& wall = out.surfaces[0];
  std::array<float, 3> lo{1e9f, 1e9f, 1e9f}, hi{-1e9f, -1e9f, -1e9f};
  for (std::size_t i = 0; i + 2 < wall.positions.size(); i += 3)
    for (int k = 0; k < 3; ++k) {
      lo[std::size_t(k)] = std::min(lo[std::size_t(k)], wall.positions[i + std::size_t(k)]);
      hi[std::size_t(k)] = std::max(hi[std::size_t(k)], wall.positions[i + std::size_t(k)]);
    }
  float r2 = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    out.centre[k] = 0.5f * (lo[k] + hi[k]);
    r2 += 0.25f * (hi[k] - lo[k]) * (hi[k] - lo[k]);
  }
  out.radius = std::sqrt(r2);
}

const char* look_name(Look look) {
  switch (look) {
    case Look::fascia:
      return "fascia";
    case Look::fat:
      return "fat";
    case Look::ima:
      return "ima";
    case Look::heart:
      return "heart";
    case Look::chest_wall:
      return "chest_wall";
    case Look::bone:
      return "bone";
    case Look::cartilage:
      return "cartilage";
    case Look::instrument:
      return "instrument";
    case Look::electrode:
      return "electrode";
  }
  return "?";
}

}  // namespace imasim::render
