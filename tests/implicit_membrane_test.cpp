// The implicit membrane solve (physics/implicit_membrane.hpp) against closed forms: the
// strain-stiffening spring's law against finite differences, a hanging chain at rest with springs
// in their toe and past it, free fall after a cut; and the fascia's linear modulus under a point
// load, converged at one step per 5 ms.
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "geometry/grid_rectangle.hpp"
#include "physics/implicit_membrane.hpp"
#include "physics/membrane_springs.hpp"

namespace imasim::physics {
namespace {

const Vec3 kGravity(0, -9.81, 0);

StiffeningSpring chain_spring() {
  StiffeningSpring s;
  s.rest_length = 0.01;
  s.toe_stiffness = 40;
  s.linear_stiffness = 1000;
  s.toe_strain = 0.05;
  return s;
}

// The length at which the spring carries tension t: T's inverse, by bisection (T rises).
double length_at(const StiffeningSpring& s, double t) {
  double lo = s.rest_length, hi = 2 * s.rest_length;
  for (int k = 0; k < 200; ++k) {
    const double mid = 0.5 * (lo + hi);
    (tension(s, mid) < t ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

TEST(StiffeningSpring, TensionAndStiffnessAreTheEnergysDerivatives) {
  const StiffeningSpring s = chain_spring();
  const double l0 = s.rest_length, lt = l0 * (1 + s.toe_strain);
  EXPECT_EQ(tension(s, l0), 0);
  EXPECT_EQ(energy(s, l0), 0);
  for (double l = 0.008; l < 0.013; l += 1e-4) {
    const double step = 1e-7;  // central differences: T = dE/dl, k = dT/dl
    // (the differences' truncation, k' step^2 / 6, is a few 1e-9 N where k rises fastest)
    EXPECT_NEAR(tension(s, l), (energy(s, l + step) - energy(s, l - step)) / (2 * step), 1e-8)
        << "l = " << l;
    EXPECT_NEAR(stiffness_at(s, l), (tension(s, l + step) - tension(s, l - step)) / (2 * step),
                1e-4)
        << "l = " << l;
  }
  // The toe's stiffness at rest and in compression, the linear one from the toe strain on,
  // rising in between; past the toe, T is the linear law offset by half the toe's recruitment.
  EXPECT_EQ(stiffness_at(s, 0.009), 40);
  EXPECT_EQ(stiffness_at(s, l0), 40);
  EXPECT_NEAR(stiffness_at(s, lt), 1000, 1e-9);
  EXPECT_EQ(stiffness_at(s, 0.012), 1000);
  EXPECT_NEAR(stiffness_at(s, l0 * (1 + s.toe_strain / 2)), 520, 1e-9);
  EXPECT_NEAR(tension(s, 0.012), 40 * 0.002 + (1000 - 40) * (0.002 - 0.5 * s.toe_strain * l0),
              1e-12);
  EXPECT_FALSE(past_toe(s, lt * 0.999));
  EXPECT_TRUE(past_toe(s, lt * 1.001));
}

TEST(ImplicitMembrane, AHangingChainRestsWhereEachSpringCarriesTheWeightBelowIt) {
  // Eight vertices hanging from the first: the lower two springs stay in their toe, the upper
  // five are past it.
  constexpr std::uint32_t n = 8;
  constexpr double m = 0.01;  // (unit: kg)
  std::vector<Real> mass(n, m);
  std::vector<std::uint8_t> fixed(n, 0);
  fixed[0] = 1;
  std::vector<MembraneEdge> edges;
  std::vector<Vec3> x, v(n, Vec3::Zero());
  for (std::uint32_t k = 0; k < n; ++k)
    x.push_back(Vec3(0, -0.01 * k, 0));
  for (std::uint32_t k = 0; k + 1 < n; ++k)
    edges.push_back({k, k + 1, chain_spring()});
  ImplicitMembrane chain(mass, fixed, edges, 0.005);
  ImplicitStepReport report;
  // 20 s: backward Euler's damping of the chain's slowest mode (about 25 rad/s) is slow.
  for (int step = 0; step < 4000; ++step)
    report = chain.step(x, v, {kGravity, {}, {}, {}}, {8, 1e-12});
  ASSERT_TRUE(report.ok);
  EXPECT_LT(report.residual, 1e-12);
  double y = 0;
  int toe = 0, linear = 0;
  for (std::uint32_t k = 0; k + 1 < n; ++k) {
    const double carried = double(n - 1 - k) * m * 9.81;  // the weight below spring k (unit: N)
    const StiffeningSpring s = chain_spring();
    y -= length_at(s, carried);
    (past_toe(s, length_at(s, carried)) ? linear : toe) += 1;
    EXPECT_NEAR(x[k + 1].y(), y, 1e-10) << "vertex " << k + 1;
    EXPECT_NEAR(v[k + 1].norm(), 0, 1e-9);
  }
  EXPECT_EQ(toe, 2);
  EXPECT_EQ(linear, 5);
}

TEST(ImplicitMembrane, AVertexCutLooseFallsAsTheDiscreteFreeFall) {
  std::vector<Vec3> x = {Vec3(0, 0, 0), Vec3(0, -0.01, 0), Vec3(0, -0.02, 0)};
  std::vector<Vec3> v(3, Vec3::Zero());
  ImplicitMembrane chain({0.001, 0.001, 0.001}, {1, 0, 0},
                         {{0, 1, chain_spring()}, {1, 2, chain_spring()}}, 0.005);
  chain.remove_edge(1);
  const Vec3 start = x[2];
  constexpr int steps = 20;
  for (int step = 0; step < steps; ++step)
    ASSERT_TRUE(chain.step(x, v, {kGravity, {}, {}, {}}, {}).ok);
  // Backward Euler with nothing but gravity: x_n = x_0 + h^2 g n (n + 1) / 2.
  const double h = 0.005;
  EXPECT_NEAR(x[2].y(), start.y() - 9.81 * h * h * steps * (steps + 1) / 2, 1e-12);
  // The vertex still hung from the fixed one sags by far less.
  EXPECT_GT(x[1].y(), -0.0105);
}

// A 50 mm square of fascia, perimeter fixed, pressed at its centre by a point force ramped to
// 0.3 N over 0.2 s; the centre's deflection at 0.5 s.
struct PressedSquare {
  double deflection = 0;
  double residual = 0;
  std::uint32_t most_iterations = 0;  // Newton iterations in the hardest step
  std::size_t stiff_edges = 0;
};

PressedSquare press_square(double linear_modulus, double h, const ImplicitSolveParams& solve) {
  const geometry::TriangleMesh mesh = geometry::make_grid_rectangle({0.05, 0.05, 21, 21});
  StiffeningMembrane fascia;
  fascia.toe_modulus = 0.1e6;
  fascia.linear_modulus = linear_modulus;
  fascia.toe_strain = 0.05;
  fascia.thickness = 1e-3;
  fascia.density = 1100;
  std::vector<std::uint8_t> fixed(mesh.vertices.size(), 0);
  for (std::uint32_t j = 0; j < 21; ++j)
    for (std::uint32_t i = 0; i < 21; ++i)
      fixed[geometry::grid_index(i, j, 21)] = i == 0 || j == 0 || i == 20 || j == 20;
  const std::vector<MembraneEdge> springs = membrane_springs(mesh, fascia);
  ImplicitMembrane membrane(membrane_masses(mesh, fascia), fixed, springs, h);
  std::vector<Vec3> x = mesh.vertices, v(x.size(), Vec3::Zero()), force(x.size(), Vec3::Zero());
  const std::uint32_t centre = geometry::grid_index(10, 10, 21);
  const int steps = static_cast<int>(std::lround(0.5 / h));
  PressedSquare out;
  for (int k = 1; k <= steps; ++k) {
    force[centre] = Vec3(0, -0.3 * std::min(1.0, k * h / 0.2), 0);
    const ImplicitStepReport r = membrane.step(x, v, {kGravity, force, {}, {}}, solve);
    EXPECT_TRUE(r.ok);
    out.residual = std::max(out.residual, double(r.residual));
    out.most_iterations = std::max(out.most_iterations, r.iterations);
  }
  out.deflection = -x[centre].y();
  for (const MembraneEdge& e : springs)
    out.stiff_edges += past_toe(e.spring, (x[e.i] - x[e.j]).norm());
  return out;
}

TEST(ImplicitMembrane, TheFasciasLinearModulusUnderAPointLoadIsConvergedAtOneStepPerFiveMs) {
  const ImplicitSolveParams solve;  // the defaults
  const PressedSquare coarse = press_square(2.65e6, 0.005, solve);
  const PressedSquare fine = press_square(2.65e6, 0.00125, solve);
  // Within 5 % of the 4 times finer step (docs/physics.md; it agrees to 1e-6), with the edges
  // under the load past their toe.
  EXPECT_NEAR(coarse.deflection, fine.deflection, 0.05 * fine.deflection);
  EXPECT_GT(coarse.stiff_edges, 0u);
  // Every step solved: the force imbalance left is below the tolerance, within its iterations.
  EXPECT_LT(coarse.residual, solve.tolerance);
  EXPECT_LE(coarse.most_iterations, solve.max_iterations);
  // The stiff end matters: with the toe's modulus throughout the centre sinks about twice as
  // deep (12.7 against 6.5 mm).
  const PressedSquare soft = press_square(0.1e6, 0.005, solve);
  EXPECT_GT(soft.deflection, 1.5 * coarse.deflection);
}

// A flat hinge, its wings at different places along the edge and heights over it.
geometry::TriangleMesh flat_hinge() {
  geometry::TriangleMesh mesh;
  mesh.vertices = {Vec3(0, 0, 0), Vec3(0.004, 0, 0), Vec3(0.0013, 0, 0.0031),
                   Vec3(0.0027, 0, -0.0022)};
  mesh.triangles = {{0, 1, 2}, {1, 0, 3}};
  return mesh;
}

Vec3 curvature(const MembraneHinge& h, const std::vector<Vec3>& x) {
  Vec3 sum = Vec3::Zero();
  for (int p = 0; p < 4; ++p)
    sum += h.w[p] * x[h.v[p]];
  return sum;
}

TEST(MembraneHinge, VanishesOnAffineImagesAndMeasuresTheDihedralAngle) {
  const geometry::TriangleMesh mesh = flat_hinge();
  const std::vector<MembraneHinge> hinges = membrane_hinges(mesh, 2e-5);
  ASSERT_EQ(hinges.size(), 1u);
  const MembraneHinge& h = hinges[0];
  EXPECT_NEAR(h.w[0] + h.w[1] + h.w[2] + h.w[3], 0, 1e-9);
  EXPECT_LT(curvature(h, mesh.vertices).norm(), 1e-12);
  // k = D |e|^2 / (A_1 + A_2), the XPBD dihedral row's.
  const double area = 0.5 * 0.004 * (0.0031 + 0.0022);
  EXPECT_NEAR(h.stiffness, 2e-5 * 0.004 * 0.004 / area, 1e-15);
  // An affine image of the rest (a shear and stretch in its plane, turned and moved): flat.
  Mat3 in_plane;
  in_plane << 1.3, 0, 0.4, 0, 1, 0, -0.2, 0, 0.8;
  const Mat3 turn = Eigen::AngleAxis<Real>(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  std::vector<Vec3> image;
  for (const Vec3& p : mesh.vertices)
    image.push_back(turn * in_plane * p + Vec3(0.1, -0.2, 0.3));
  EXPECT_LT(curvature(h, image).norm(), 1e-12);
  // A wing turned about the edge by theta: |sum w x| = 2 sin(theta / 2), theta for small bends.
  for (double theta : {0.01, 0.1, 0.5, 1.0}) {
    std::vector<Vec3> bent = mesh.vertices;
    bent[3] = Eigen::AngleAxis<Real>(theta, Vec3::UnitX()) * bent[3];
    EXPECT_NEAR(curvature(h, bent).norm(), 2 * std::sin(theta / 2), 1e-12) << theta;
  }
}

TEST(ImplicitMembrane, AHingeHeldAtItsEdgeCarriesAWingsWeightByBending) {
  // The edge's ends and one wing fixed, the other wing free under gravity, its edges stiff: it
  // turns about the edge until its weight's moment m g h3 cos(theta) balances the hinge's
  // dE/dtheta = d/dtheta (k/2 (2 sin(theta/2))^2) = k sin(theta).
  const geometry::TriangleMesh mesh = flat_hinge();
  std::vector<MembraneHinge> hinges = membrane_hinges(mesh, 2e-5);
  StiffeningSpring stiff;
  std::vector<MembraneEdge> edges;
  for (auto [i, j] : {std::pair{0u, 1u}, {0u, 2u}, {1u, 2u}, {0u, 3u}, {1u, 3u}}) {
    stiff.rest_length = (mesh.vertices[i] - mesh.vertices[j]).norm();
    stiff.toe_stiffness = stiff.linear_stiffness = 1e6;
    stiff.toe_strain = 1;
    edges.push_back({i, j, stiff});
  }
  const double m = 1e-4;
  ImplicitMembrane hinge({1, 1, 1, m}, {1, 1, 1, 0}, edges, 0.005, hinges);
  std::vector<Vec3> x = mesh.vertices, v(4, Vec3::Zero());
  for (int step = 0; step < 2000; ++step)
    ASSERT_TRUE(hinge.step(x, v, {kGravity, {}, {}, {}}, {}).ok);
  const double h3 = 0.0022, k = hinges[0].stiffness;
  const double theta = std::atan2(-x[3].y(), -x[3].z());  // the wing's turn about the edge (x)
  EXPECT_GT(theta, 0.05);
  EXPECT_NEAR(k * std::sin(theta), m * 9.81 * h3 * std::cos(theta), 1e-3 * m * 9.81 * h3);
}

TEST(ImplicitMembrane, AWingWhoseHingeIsCutFallsFreelyInOneNewtonIterationAStep) {
  // The wing held by its hinge alone; once the hinge is cut, its step is the quadratic of its mass
  // and gravity, which one Newton iteration solves exactly if the matrix lost the hinge too.
  const geometry::TriangleMesh mesh = flat_hinge();
  const double m = 1e-4, h = 0.005;
  ImplicitMembrane hinge({1, 1, 1, m}, {1, 1, 1, 0}, {}, h, membrane_hinges(mesh, 2e-5));
  std::vector<Vec3> x = mesh.vertices, v(4, Vec3::Zero());
  for (int step = 0; step < 20; ++step)
    ASSERT_TRUE(hinge.step(x, v, {kGravity, {}, {}, {}}, {}).ok);
  hinge.remove_hinge(0);
  const Vec3 start = x[3], speed = v[3];
  constexpr int steps = 10;
  for (int step = 0; step < steps; ++step) {
    const ImplicitStepReport report = hinge.step(x, v, {kGravity, {}, {}, {}}, {});
    ASSERT_TRUE(report.ok);
    EXPECT_EQ(report.iterations, 1u) << "step " << step;
  }
  // Backward Euler under gravity alone: x_n = x_0 + n h v_0 + h^2 g n (n + 1) / 2.
  const Vec3 expected = start + steps * h * speed + h * h * kGravity * steps * (steps + 1) / 2.0;
  EXPECT_NEAR((x[3] - expected).norm(), 0, 1e-12);
}

TEST(ImplicitMembrane, ABodyOnItsSpringPressesAVertexAsSpringsInSeries) {
  // A vertex hung 10 mm under a fixed one on a spring (no gravity); under it a body held by its
  // coupling to an anchor 2 mm above the vertex's rest, pushing it up through a contact plane
  // 1 mm above the body's centre. At rest the coupling, the spring (compressed) and the contact's
  // penalty carry one force in series: f = D / (1/k_b + 1/k_s + 1/k_c), D the overlap the anchor
  // asks for.
  StiffeningSpring spring;
  spring.rest_length = 0.01;
  spring.toe_stiffness = spring.linear_stiffness = 50;
  spring.toe_strain = 1;
  ImplicitMembrane rig({1, 0.001}, {1, 0}, {{0, 1, spring}}, 0.005, {}, 1);
  std::vector<Vec3> x = {Vec3(0, 0, 0), Vec3(0, -0.01, 0)}, v(2, Vec3::Zero());
  const double kb = 1000, reach = 0.001;
  std::vector<MembraneBody> body = {{Vec3(0, -0.01 + 0.002 - reach, 0), kb, 5, Vec3(0, -0.02, 0)}};
  const ImplicitSolveParams solve;
  for (int step = 0; step < 400; ++step) {
    const std::vector<MembraneContact> contact = {
        {1, body[0].position + Vec3(0, reach, 0), Vec3::UnitY(), 0}};
    const Vec3 start = body[0].position;
    ASSERT_TRUE(rig.step(x, v, {Vec3::Zero(), {}, contact, body}, solve).ok);
    if (step + 1 < 400) continue;
    const double f =
        contact_force(contact[0], x[1], solve.contact_stiffness, body[0].position - start);
    const double expected = 0.002 / (1 / kb + 1 / 50.0 + 1 / solve.contact_stiffness);
    // To the solve's tolerance (a force imbalance, unit: N).
    EXPECT_NEAR(f, expected, solve.tolerance);
    EXPECT_NEAR(kb * (body[0].anchor - body[0].position).y(), f, solve.tolerance);
    EXPECT_NEAR(50 * (x[1].y() + 0.01), f, solve.tolerance);
  }
}

TEST(ImplicitMembrane, RefusesWhatItCannotSolveNamingIt) {
  auto message = [](auto make) {
    try {
      make();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_NE(message([] {
              ImplicitMembrane({1, 1}, {0}, {}, 0.005);
            }).find("fixed flags"),
            std::string::npos);
  EXPECT_NE(message([] {
              ImplicitMembrane({0, 1}, {0, 1}, {}, 0.005);
            }).find("vertex 0"),
            std::string::npos);
  EXPECT_NE(message([] {
              ImplicitMembrane({1, 1}, {0, 1}, {{0, 5, chain_spring()}}, 0.005);
            }).find("edge 0"),
            std::string::npos);
  StiffeningSpring softer = chain_spring();
  softer.linear_stiffness = 1;
  EXPECT_NE(message([&] {
              ImplicitMembrane({1, 1}, {0, 1}, {{0, 1, softer}}, 0.005);
            }).find("linear stiffness"),
            std::string::npos);
  EXPECT_NE(message([] { ImplicitMembrane({1}, {0}, {}, 0); }).find("step h"), std::string::npos);
}

}  // namespace
}  // namespace imasim::physics
