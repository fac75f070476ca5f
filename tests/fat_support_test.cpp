// The fat's columns (tissue/fat_support.hpp, physics/support_row.hpp): a column resists
// compression with its stiffness and never pulls; the rows in the thoracic patch carry the
// strands' stiffness to the surfaces they hold; the fascia laid on its fat rests on it.
#include "tissue/fat_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "geometry/grid_rectangle.hpp"
#include "physics/executor.hpp"
#include "physics/implicit_membrane.hpp"
#include "physics/membrane_springs.hpp"
#include "physics/support_row.hpp"
#include "tissue/strands.hpp"
#include "tissue/thoracic_patch.hpp"
#include "tissue/tissue_step.hpp"

namespace imasim {
namespace {

constexpr double kG = 9.81;

// XPBD substeps of one particle (mass m) under gravity -y on a column (plane y = 0, stiffness
// k): x_pred = x + h v + h^2 g, the row projected once, v = (x - x_old) / h.
struct Particle {
  Vec3 x = Vec3::Zero(), v = Vec3::Zero();
};

physics::SupportRow column_at_origin(double k) {
  physics::SupportRow r;
  r.particle = 0;
  r.normal = Vec3::UnitY();
  r.offset = 0;
  r.compliance = 1 / k;
  return r;
}

void substep(Particle& p, physics::SupportRow& r, double m, double h) {
  const Vec3 old = p.x;
  p.x += h * p.v + h * h * Vec3(0, -kG, 0);
  r.lambda = 0;
  const Real w = 1 / m;
  physics::project_support(r, &p.x, &w, h);
  p.v = (p.x - old) / h;
}

TEST(SupportRow, AParticleRestsWhereItsColumnCarriesItsWeight) {
  const double m = 2e-4, k = 4.0, h = 0.005 / 32;
  Particle p;
  physics::SupportRow r = column_at_origin(k);
  for (int s = 0; s < 32 * 2000; ++s) {
    p.v *= 0.999;  // a little damping so that it settles
    substep(p, r, m, h);
  }
  // XPBD's fixed point of a linear row is the spring's: y = -m g / k, exactly.
  EXPECT_NEAR(p.x.y(), -m * kG / k, 1e-9 * m * kG / k + 1e-15);
  // The push over the last substep is the weight: lambda / h^2.
  EXPECT_NEAR(r.lambda / (h * h), m * kG, 1e-6 * m * kG);
}

TEST(SupportRow, AColumnNeverPulls) {
  const double m = 2e-4, h = 0.005 / 32;
  Particle p;
  p.x = Vec3(0, 1e-3, 0);
  p.v = Vec3(0, 0.1, 0);  // moving away from the base
  physics::SupportRow r = column_at_origin(4.0);
  for (int s = 0; s < 32; ++s)
    substep(p, r, m, h);
  EXPECT_EQ(r.lambda, 0);
  EXPECT_EQ(r.impulse, 0);
  // Free flight: y = y0 + v t - g t^2 / 2 over the discrete steps (semi-implicit Euler).
  const double t = 32 * h;
  EXPECT_NEAR(p.x.y(), 1e-3 + 0.1 * t - 0.5 * kG * t * t - 0.5 * kG * h * t, 1e-12);
}

TEST(SupportRow, AColumnThatHoldsBothWaysCarriesAHangingParticle) {
  const double m = 2e-4, k = 4.0, h = 0.005 / 32;
  Particle p;
  physics::SupportRow r = column_at_origin(k);
  r.normal = -Vec3::UnitY();  // its base above: gravity stretches it
  r.pushes_only = false;
  for (int s = 0; s < 32 * 2000; ++s) {
    p.v *= 0.999;
    substep(p, r, m, h);
  }
  EXPECT_NEAR(p.x.y(), -m * kG / k, 1e-9 * m * kG / k);
  EXPECT_NEAR(-r.lambda / (h * h), m * kG, 1e-6 * m * kG) << "a pull";
}

TEST(SupportRow, TheImplicitMembraneRestsAVertexWhereItsColumnCarriesIt) {
  const double m = 2e-4, k = 4.0, h = 0.005;
  physics::ImplicitMembrane membrane({m}, {0}, {}, h);
  std::vector<Vec3> x{Vec3::Zero()}, v{Vec3::Zero()};
  const std::vector<physics::MembraneSupport> supports{{0, Vec3::Zero(), Vec3::UnitY(), k}};
  for (int s = 0; s < 400; ++s) {
    physics::ImplicitLoads loads{Vec3(0, -kG, 0), {}, {}, {}};
    loads.supports = supports;
    physics::ImplicitSolveParams solve;
    solve.tolerance = 1e-13;  // (unit: N)
    ASSERT_TRUE(membrane.step(x, v, loads, solve).ok);
  }
  EXPECT_NEAR(x[0].y(), -m * kG / k, 1e-6 * m * kG / k);
}

// Each fascia vertex's row, against the strands bound to its faces (recounted here).
tissue::ThoracicPatchParams with_columns() {
  tissue::ThoracicPatchParams params = tissue::default_thoracic_patch_params();
  params.fascia_fat.resists_compression = true;
  params.ima_fat.resists_compression = true;
  return params;
}

TEST(FatSupport, TheFasciasRowsCarryTheStrandsBoundToIt) {
  tissue::ThoracicPatch patch = tissue::make_thoracic_patch(with_columns());
  tissue::TissueWorld& w = patch.world;
  tissue::StrandSet& set = w.strands[patch.fascia_fat];
  const tissue::MeshObject& fascia = w.meshes[patch.fascia];
  ASSERT_EQ(set.column_stiffness.size(), set.strand_count);
  const physics::Particles& P = w.state.particles;
  auto expected = [&] {
    std::vector<double> k(P.size(), 0);
    for (std::uint32_t s = 0; s < set.strand_count; ++s) {
      if (set.cut[s] != tissue::kStrandIntact) continue;
      const geometry::Triangle& face = fascia.triangles[set.end_a[s].triangle];
      for (int c = 0; c < 3; ++c)
        k[fascia.first_particle + face[c]] += set.end_a[s].bary[c] * set.column_stiffness[s];
    }
    return k;
  };
  // Each held vertex has three rows, in order: along its columns (k, returned per particle),
  // then across them on two directions (2/3 k each, the fat's shear: fat_support.hpp), the three
  // directions orthonormal.
  auto rows_on_fascia = [&] {
    std::vector<double> k(P.size(), 0);
    std::vector<const physics::SupportRow*> rows;
    for (const physics::SupportRow& r : w.state.supports) {
      if (r.particle < fascia.first_particle ||
          r.particle >= fascia.first_particle + fascia.particle_count)
        continue;
      EXPECT_NEAR(r.normal.norm(), 1, 1e-12);
      EXPECT_FALSE(r.pushes_only) << "the fat holds the fascia both ways";
      EXPECT_NEAR(r.normal.dot(P.rest_position[r.particle]), r.offset, 1e-15);
      rows.push_back(&r);
    }
    EXPECT_EQ(rows.size() % 3, 0u);
    for (std::size_t n = 0; n + 2 < rows.size(); n += 3) {
      const physics::SupportRow &along = *rows[n], &a = *rows[n + 1], &b = *rows[n + 2];
      EXPECT_EQ(a.particle, along.particle);
      EXPECT_EQ(b.particle, along.particle);
      EXPECT_EQ(k[along.particle], 0) << "three rows a vertex";
      k[along.particle] = 1 / along.compliance;
      EXPECT_LT(along.normal.y(), -0.5) << "away from the wall, above the cavity";
      EXPECT_NEAR(a.compliance, 1.5 * along.compliance, 1e-12 * a.compliance);
      EXPECT_NEAR(b.compliance, 1.5 * along.compliance, 1e-12 * b.compliance);
      EXPECT_NEAR(a.normal.dot(along.normal), 0, 1e-12);
      EXPECT_NEAR(b.normal.dot(along.normal), 0, 1e-12);
      EXPECT_NEAR(a.normal.dot(b.normal), 0, 1e-12);
    }
    return k;
  };
  // At set-up every particle is on its plane: every dynamic vertex with a column has its row.
  tissue::gather_fat_supports(w);
  std::vector<double> want = expected(), got = rows_on_fascia();
  std::size_t with_rows = 0;
  for (std::uint32_t v = 0; v < fascia.particle_count; ++v) {
    const std::uint32_t i = fascia.first_particle + v;
    if (P.inverse_mass[i] == 0) {
      EXPECT_EQ(got[i], 0);
      continue;
    }
    EXPECT_NEAR(got[i], want[i], 1e-12 * want[i]) << "vertex " << v;
    with_rows += got[i] > 0;
  }
  EXPECT_GT(with_rows, fascia.particle_count / 2);
  // Divided strands carry no column.
  for (std::uint32_t s = 0; s < set.strand_count; s += 2)
    set.cut[s] = tissue::kStrandDivided;
  tissue::gather_fat_supports(w);
  want = expected();
  got = rows_on_fascia();
  for (std::uint32_t v = 0; v < fascia.particle_count; ++v) {
    const std::uint32_t i = fascia.first_particle + v;
    if (P.inverse_mass[i] > 0) {
      EXPECT_NEAR(got[i], want[i], 1e-12 * want[i] + 1e-15);
    }
  }
  // A strand's interior particle: the column below it, E A_s / h.
  const std::uint32_t s = 1, i = set.particle(s, 1);
  const Vec3& base = P.rest_position[set.particle(s, set.segments)];
  const double length = (P.rest_position[set.particle(s, 0)] - base).norm();
  const double height = set.column_direction[s].dot(P.rest_position[i] - base);
  const auto row = std::find_if(w.state.supports.begin(), w.state.supports.end(),
                                [&](const physics::SupportRow& r) { return r.particle == i; });
  ASSERT_NE(row, w.state.supports.end());
  EXPECT_TRUE(row->pushes_only) << "the strand's chain pulls, its column pushes";
  EXPECT_NEAR(1 / row->compliance, set.column_stiffness[s] * length / height,
              1e-9 * set.column_stiffness[s] * length / height);
}

// By default the IMA's fat has its columns (it holds the vessel and pushes back on a hook) and
// the fascia's has none: every row is the vessel's or its fat's.
TEST(FatSupport, TheDefaultStrandsGiveRowsForTheVesselsFatOnly) {
  tissue::ThoracicPatch patch =
      tissue::make_thoracic_patch(tissue::default_thoracic_patch_params());
  tissue::gather_fat_supports(patch.world);
  const tissue::TissueWorld& w = patch.world;
  const tissue::MeshObject& ima = w.meshes[patch.ima];
  const tissue::StrandSet& fat = w.strands[patch.ima_fat];
  const std::uint32_t fat_end = fat.first_particle + fat.strand_count * (fat.segments + 1);
  std::size_t vessel_rows = 0;
  for (const physics::SupportRow& r : w.state.supports) {
    const bool of_vessel =
        r.particle >= ima.first_particle && r.particle < ima.first_particle + ima.particle_count;
    const bool of_its_fat = r.particle >= fat.first_particle && r.particle < fat_end;
    EXPECT_TRUE(of_vessel || of_its_fat) << "particle " << r.particle;
    vessel_rows += of_vessel;
  }
  // Three rows (along the columns, two across) for each vertex a strand is bound near.
  EXPECT_GT(vessel_rows, ima.particle_count);
  EXPECT_EQ(vessel_rows % 3, 0u);
}

// A column needs a base that does not move: strands to the fascia (dynamic) are refused, by
// their set's name, rather than built without columns.
TEST(FatSupport, ColumnsToABaseThatMovesAreRefused) {
  tissue::ThoracicPatch patch =
      tissue::make_thoracic_patch(tissue::default_thoracic_patch_params());
  tissue::StrandSetParams params;
  params.name = "vessel_to_fascia";
  params.resists_compression = true;
  try {
    tissue::add_strands(patch.world, patch.ima, patch.fascia, params);
    FAIL() << "accepted";
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("vessel_to_fascia"), std::string::npos) << what;
    EXPECT_NE(what.find("resists_compression"), std::string::npos) << what;
  }
}

// The fascia laid on its fat (its gravity turned towards the wall): a load on a foundation of
// columns. Over the middle of the sheet, away from its fixed edges, the columns carry the
// weight: the stiffness-weighted mean sink along the columns is the weight along them over their
// stiffness, sum m g n / sum k (the membrane and the bending only move load between neighbours,
// whose columns differ with the strands' random binding). Without the columns the strands buckle
// and the fascia falls towards the wall.
struct Sink {
  double mean = 0, expected = 0;  // (unit: m)
};

Sink middle_sink(bool columns) {
  tissue::ThoracicPatchParams params = with_columns();
  params.fascia_fat.resists_compression = columns;
  tissue::ThoracicPatch patch = tissue::make_thoracic_patch(params);
  tissue::TissueWorld& w = patch.world;
  const tissue::MeshObject& fascia = w.meshes[patch.fascia];
  w.model.objects[fascia.object].gravity = Vec3(0, kG, 0);
  physics::Particles& P = w.state.particles;
  Vec3 low = Vec3::Constant(1e9), high = -low;
  for (std::uint32_t v = 0; v < fascia.particle_count; ++v) {
    low = low.cwiseMin(P.rest_position[fascia.first_particle + v]);
    high = high.cwiseMax(P.rest_position[fascia.first_particle + v]);
  }
  auto in_middle = [&](const Vec3& x) {
    const Vec3 u = (x - low).cwiseQuotient((high - low).cwiseMax(Vec3::Constant(1e-9)));
    return std::abs(u.x() - 0.5) < 0.3 && std::abs(u.z() - 0.5) < 0.3;
  };
  physics::Executor exec(1);
  for (int s = 0; s < 600; ++s)
    if (!tissue::step_tissue(w, exec).ok()) return {-1, -1};
  tissue::gather_fat_supports(w);
  Sink out;
  double k_sum = 0, weight = 0, pushed = 0;
  for (const physics::SupportRow& r : w.state.supports) {
    if (r.particle < fascia.first_particle ||
        r.particle >= fascia.first_particle + fascia.particle_count ||
        !in_middle(P.rest_position[r.particle]))
      continue;
    const double k = 1 / r.compliance;
    k_sum += k;
    weight += -kG * r.normal.y() / P.inverse_mass[r.particle];  // along the column (unit: N)
    pushed += k * -r.normal.dot(P.position[r.particle] - P.rest_position[r.particle]);
  }
  if (!(k_sum > 0)) {  // no columns: the plain mean sink towards the wall of the same vertices
    double n = 0;
    for (std::uint32_t v = 0; v < fascia.particle_count; ++v) {
      const std::uint32_t i = fascia.first_particle + v;
      if (P.inverse_mass[i] == 0 || !in_middle(P.rest_position[i])) continue;
      out.mean += P.position[i].y() - P.rest_position[i].y();
      n += 1;
    }
    out.mean /= std::max(n, 1.0);
    return out;
  }
  out.mean = pushed / k_sum;
  out.expected = weight / k_sum;
  return out;
}

TEST(FatSupport, TheFasciaLaidOnItsFatSinksItsWeightOverItsColumns) {
  const Sink with = middle_sink(true);
  ASSERT_GT(with.expected, 0);
  EXPECT_NEAR(with.mean, with.expected, 0.05 * with.expected);
  const Sink without = middle_sink(false);
  EXPECT_GT(without.mean, 3 * with.expected) << "without the columns it falls towards the wall";
}

// A plate on an elastic foundation under a point force (Hetenyi): the centre sinks F / (8
// sqrt(D k_w)), D the plate's bending stiffness and k_w the foundation's stiffness per area, and
// the deflection fades over (D / k_w)^(1/4). The fascia's bending on its fat: D of the toe's
// modulus (docs/tissue.md), k_w = E_fat / L of 10 mm of fat; each vertex's column is k_w times
// its third of its triangles' area. Solved quasi-statically by the implicit membrane (steps of
// 1 s), a 40 mm square of the fascia with its perimeter fixed, 20 of the decay lengths wide.
double plate_sink(std::uint32_t n, double force) {
  const double size = 0.04, e = 0.1e6, t = 1e-3, nu = 0.45;
  const double d = e * t * t * t / (12 * (1 - nu * nu));  // (unit: N m)
  const double k_w = 3250 / 0.010;                        // (unit: N/m^3)
  const geometry::TriangleMesh mesh = geometry::make_grid_rectangle({size, size, n, n});
  physics::StiffeningMembrane fascia;
  fascia.toe_modulus = fascia.linear_modulus = e;
  fascia.toe_strain = 0.05;
  fascia.thickness = t;
  fascia.density = 1100;
  std::vector<std::uint8_t> fixed(mesh.vertices.size(), 0);
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i)
      fixed[geometry::grid_index(i, j, n)] = i == 0 || j == 0 || i == n - 1 || j == n - 1;
  std::vector<double> area(mesh.vertices.size(), 0);
  for (const geometry::Triangle& tri : mesh.triangles) {
    const double a = 0.5 * (mesh.vertices[tri[1]] - mesh.vertices[tri[0]])
                               .cross(mesh.vertices[tri[2]] - mesh.vertices[tri[0]])
                               .norm();
    for (std::uint32_t c : tri)
      area[c] += a / 3;
  }
  std::vector<physics::MembraneSupport> supports;
  for (std::uint32_t v = 0; v < mesh.vertices.size(); ++v)
    if (!fixed[v]) supports.push_back({v, mesh.vertices[v], Vec3::UnitY(), k_w * area[v], false});
  const double h = 1;
  physics::ImplicitMembrane membrane(physics::membrane_masses(mesh, fascia), fixed,
                                     physics::membrane_springs(mesh, fascia), h,
                                     physics::membrane_hinges(mesh, d));
  std::vector<Vec3> x = mesh.vertices, v(x.size(), Vec3::Zero());
  const std::uint32_t centre = geometry::grid_index(n / 2, n / 2, n);
  std::vector<Vec3> f(x.size(), Vec3::Zero());
  f[centre] = Vec3(0, -force, 0);
  physics::ImplicitSolveParams solve;
  solve.tolerance = 1e-12;
  for (int s = 0; s < 6; ++s) {
    physics::ImplicitLoads loads{Vec3::Zero(), f, {}, {}};
    loads.supports = supports;
    if (!membrane.step(x, v, loads, solve).ok) return -1;
  }
  return mesh.vertices[centre].y() - x[centre].y();
}

TEST(FatSupport, TheFasciaOnItsFatBendsAsAPlateOnAnElasticFoundation) {
  const double force = 1e-4;  // small: the sheet's stretch adds nothing at 10 um
  const double d = 0.1e6 * 1e-9 / (12 * (1 - 0.45 * 0.45)), k_w = 3250 / 0.010;
  const double closed_form = force / (8 * std::sqrt(d * k_w));
  const double fine = plate_sink(61, force);  // 0.67 mm spacing
  EXPECT_NEAR(fine, closed_form, 0.05 * closed_form);
}

}  // namespace
}  // namespace imasim
