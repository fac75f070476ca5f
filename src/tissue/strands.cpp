#include "tissue/strands.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geometry/uniform_grid.hpp"
#include "physics/constraint_system.hpp"
#include "physics/mesh_constraints.hpp"
#include "tissue/mesh_object.hpp"

namespace imasim::tissue {

namespace {

physics::ObjectId add_object_for_strands(TissueWorld& world, const StrandSetParams& p) {
  return add_object(world, p.name, p.gravity, p.linear_damping, 0, p.coarse);
}

geometry::TriangleMesh current_mesh(const TissueWorld& w, const MeshObject& m) {
  geometry::TriangleMesh mesh;
  const auto x = mesh_positions(w, m);
  mesh.vertices.assign(x.begin(), x.end());
  mesh.triangles = m.triangles;
  return mesh;
}

// Each pair of interior particles within `radius` at rest, listed once from its lower index.
void build_neighbours(StrandSet& set, const physics::Particles& P) {
  const std::uint32_t count = set.particle_count();
  std::vector<geometry::Box> boxes;
  boxes.reserve(count);
  for (std::uint32_t k = 0; k < count; ++k)
    boxes.emplace_back(P.rest_position[set.first_particle + k]);
  const geometry::UniformGrid grid(boxes, set.xsph_radius);
  std::vector<std::uint32_t> visited;
  std::uint32_t stamp = 0;
  const std::uint32_t per = set.segments + 1;
  set.pair_start.assign(1, 0u);
  for (std::uint32_t k = 0; k < count; ++k) {
    const bool interior = k % per != 0 && k % per != set.segments;
    if (interior) {
      const Vec3& x = P.rest_position[set.first_particle + k];
      const Vec3 r = Vec3::Constant(set.xsph_radius);
      std::vector<std::uint32_t> found;
      grid.visit(geometry::Box(x - r, x + r), visited, stamp, [&](std::uint32_t j) {
        const bool j_interior = j % per != 0 && j % per != set.segments;
        if (j != k && j_interior &&
            (P.rest_position[set.first_particle + j] - x).squaredNorm() <
                set.xsph_radius * set.xsph_radius) {
          found.push_back(j);
        }
      });
      std::sort(found.begin(), found.end());  // grid order must not leak into the sums
      for (auto j = std::upper_bound(found.begin(), found.end(), k); j != found.end(); ++j) {
        set.pair_lower.push_back(k);
        set.pair_upper.push_back(*j);
      }
    }
    set.pair_start.push_back(static_cast<std::uint32_t>(set.pair_lower.size()));
  }
  // Counting sort by the upper particle; pairs are visited in ascending order, so each list is.
  set.incoming_start.assign(count + 1, 0u);
  for (const std::uint32_t j : set.pair_upper)
    ++set.incoming_start[j + 1];
  for (std::uint32_t k = 0; k < count; ++k)
    set.incoming_start[k + 1] += set.incoming_start[k];
  set.incoming_pair.resize(set.pair_upper.size());
  std::vector<std::uint32_t> next(set.incoming_start.begin(), set.incoming_start.end() - 1);
  for (std::uint32_t p = 0; p < set.pair_upper.size(); ++p)
    set.incoming_pair[next[set.pair_upper[p]]++] = p;
}

}  // namespace

std::uint32_t add_strands(TissueWorld& world, std::uint32_t mesh_a, std::uint32_t mesh_b,
                          const StrandSetParams& p) {
  if (mesh_a >= world.meshes.size() || mesh_b >= world.meshes.size() || mesh_a == mesh_b) {
    throw std::invalid_argument(p.name + ": strands need two different mesh objects");
  }
  if (!(p.diameter > 0) || !(p.total_mass > 0) || !(p.xsph_radius > 0) ||
      !(std::isfinite(p.youngs_modulus) && p.youngs_modulus > 0) ||
      !(p.xsph_coefficient >= 0 && p.xsph_coefficient <= 1) || !(p.tear_stretch > 1)) {
    throw std::invalid_argument(
        p.name +
        ": diameter, total_mass, youngs_modulus and xsph_radius must be > 0, "
        "xsph_coefficient in [0, 1], tear_stretch > 1");
  }
  const StrandGeneration gen =
      generate_strands(current_mesh(world, world.meshes[mesh_a]),
                       current_mesh(world, world.meshes[mesh_b]), p.generation);
  StrandSet set;
  set.name = p.name;
  set.object = add_object_for_strands(world, p);
  set.mesh_a = mesh_a;
  set.mesh_b = mesh_b;
  set.segments = p.generation.segments;
  set.strand_count = static_cast<std::uint32_t>(gen.strands.size());
  set.xsph_coefficient = p.xsph_coefficient;
  set.xsph_radius = p.xsph_radius;
  set.tear_stretch = p.tear_stretch;
  physics::Particles& P = world.state.particles;
  set.first_particle = static_cast<std::uint32_t>(P.size());
  const std::uint32_t n = set.segments;
  const Real interior_count = Real(std::max<std::size_t>(1, gen.strands.size() * (n - 1)));
  const Real particle_mass = p.total_mass / interior_count;
  // Material compliance 1/E (unit: m^2/N); a segment's row scale L / A_s (unit: 1/m), so its
  // compliance is L / (E A_s) (unit: m/N).
  const physics::MaterialId material =
      world.model.add_material(physics::ConstraintMaterial::xpbd(1 / p.youngs_modulus));
  const MeshObject& source = world.meshes[mesh_a];
  const MeshObject& base = world.meshes[mesh_b];
  bool base_fixed = true;
  for (std::uint32_t k = 0; k < base.particle_count; ++k)
    base_fixed = base_fixed && P.inverse_mass[base.first_particle + k] == 0;
  if (p.resists_compression && !base_fixed) {
    throw std::invalid_argument(p.name +
                                ": resists_compression needs a base that does not move (every "
                                "particle of the second mesh fixed)");
  }
  const bool columns = p.resists_compression;
  for (const GeneratedStrand& g : gen.strands) {
    const geometry::Triangle& face = source.triangles[g.face_a];
    const Real cross_section = physics::rest_triangle_area(P, source.first_particle, face) /
                               std::max(p.generation.strands_per_face, Real(1));
    const Real segment_length = (g.end - g.start).norm() / Real(n);
    for (std::uint32_t k = 0; k <= n; ++k) {
      const Real t = Real(k) / Real(n);
      const std::uint32_t i = P.add((1 - t) * g.start + t * g.end, particle_mass, set.object);
      if (k == 0 || k == n) P.fix(i);  // ends ride on their surfaces
      if (k > 0) {
        set.segment_constraint.push_back(physics::add_distance(
            world.state.constraints, P, i - 1, i, material, segment_length / cross_section));
      }
      set.diameter.push_back(p.diameter);
    }
    if (columns) {
      // The whole strand's stiffness, its n segments in series: E A_s / L (unit: N/m).
      const Real length = (g.start - g.end).norm();
      set.column_stiffness.push_back(length > 0 ? p.youngs_modulus * cross_section / length : 0);
      set.column_direction.push_back(length > 0 ? Vec3((g.start - g.end) / length) : Vec3::Zero());
    }
    set.end_a.push_back({g.face_a, g.bary_a, 0});
    set.end_b.push_back({g.face_b, g.bary_b, 0});
    set.face_a.push_back(g.face_a);
    set.cut.push_back(kStrandIntact);
  }
  build_neighbours(set, P);
  world.strands.push_back(std::move(set));
  world.xsph_scratch.resize(P.size());
  world.xsph_weight.resize(P.size());
  const std::size_t pairs = world.strands.back().pair_lower.size();
  if (world.xsph_kernel.size() < pairs) world.xsph_kernel.resize(pairs);
  if (world.xsph_share.size() < pairs) world.xsph_share.resize(pairs);
  return static_cast<std::uint32_t>(world.strands.size() - 1);
}

std::vector<std::uint32_t> interior_particles(const StrandSet& set) {
  std::vector<std::uint32_t> out;
  for (std::uint32_t s = 0; s < set.strand_count; ++s) {
    for (std::uint32_t k = 1; k < set.segments; ++k)
      out.push_back(set.particle(s, k));
  }
  return out;
}

void place_strand_ends(TissueWorld& world) {
  physics::Particles& P = world.state.particles;
  for (const StrandSet& set : world.strands) {
    const MeshObject& a = world.meshes[set.mesh_a];
    const MeshObject& b = world.meshes[set.mesh_b];
    for (std::uint32_t s = 0; s < set.strand_count; ++s) {
      P.position[set.particle(s, 0)] =
          geometry::bound_point(set.end_a[s], mesh_positions(world, a), a.normals, a.triangles);
      P.position[set.particle(s, set.segments)] =
          geometry::bound_point(set.end_b[s], mesh_positions(world, b), b.normals, b.triangles);
    }
  }
}

}  // namespace imasim::tissue
