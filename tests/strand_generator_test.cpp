// The connective-tissue strand generator (2.3.4): counts, geometry, determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "geometry/grid_rectangle.hpp"
#include "geometry/vertex_normals.hpp"
#include "tissue/strand_generator.hpp"

namespace imasim::tissue {
namespace {

// A: 60 x 60 mm plate at y = 0, normals +y. B: the same plate at y = gap, flipped to face A.
struct Plates {
  geometry::TriangleMesh a, b;
};

Plates plates(double gap, bool b_faces_a = true) {
  Plates p;
  p.a = geometry::make_grid_rectangle({0.06, 0.06, 21, 21});
  p.b = geometry::make_grid_rectangle({0.08, 0.08, 9, 9});
  for (Vec3& x : p.b.vertices)
    x += Vec3(-0.01, gap, -0.01);
  if (b_faces_a) {
    for (auto& t : p.b.triangles)
      std::swap(t[1], t[2]);
  }
  return p;
}

Vec3 face_unit_normal(const geometry::TriangleMesh& m, std::uint32_t f) {
  const auto& t = m.triangles[f];
  return geometry::face_normal(m.vertices[t[0]], m.vertices[t[1]], m.vertices[t[2]]).normalized();
}

TEST(StrandGenerator, CountsPerFaceAverageSigma) {
  const Plates p = plates(0.01);
  for (const double sigma : {0.3, 1.0, 2.5}) {
    StrandParams params;
    params.strands_per_face = sigma;
    params.max_length = 0.02;
    const StrandGeneration g = generate_strands(p.a, p.b, params);
    ASSERT_EQ(g.eligible_faces.size(), p.a.triangle_count());  // all 800 faces face B
    EXPECT_EQ(g.dropped, 0u);
    const double mean = double(g.strands.size()) / double(g.eligible_faces.size());
    // 800 faces: the mean's standard deviation is at most 0.5 / sqrt(800) = 0.018.
    EXPECT_NEAR(mean, sigma, 0.09) << "sigma " << sigma;
    std::map<std::uint32_t, int> per_face;
    for (const auto& s : g.strands)
      ++per_face[s.face_a];
    for (const auto& [face, count] : per_face) {
      EXPECT_GE(count, int(std::floor(sigma)));
      EXPECT_LE(count, int(std::floor(sigma)) + 1);
    }
  }
}

TEST(StrandGenerator, StrandsRespectLengthAngleAndEndpoints) {
  const Plates p = plates(0.01);
  StrandParams params;
  params.strands_per_face = 2;
  params.max_length = 0.0115;
  params.max_angle = 0.5;
  const StrandGeneration g = generate_strands(p.a, p.b, params);
  ASSERT_GT(g.strands.size(), 1000u);
  for (const GeneratedStrand& s : g.strands) {
    const Vec3 d = s.end - s.start;
    EXPECT_LE(d.norm(), params.max_length * (1 + 1e-12));
    const double angle =
        std::acos(std::clamp(d.normalized().dot(face_unit_normal(p.a, s.face_a)), -1.0, 1.0));
    EXPECT_LE(angle, params.max_angle + 1e-9);
    EXPECT_NEAR(s.start.y(), 0.0, 1e-12);  // on A
    EXPECT_NEAR(s.end.y(), 0.01, 1e-12);   // on B
    const auto& ta = p.a.triangles[s.face_a];
    const Vec3 from_bary = s.bary_a[0] * p.a.vertices[ta[0]] + s.bary_a[1] * p.a.vertices[ta[1]] +
                           s.bary_a[2] * p.a.vertices[ta[2]];
    EXPECT_LT((from_bary - s.start).norm(), 1e-12);
    const auto& tb = p.b.triangles[s.face_b];
    const Vec3 on_b = s.bary_b[0] * p.b.vertices[tb[0]] + s.bary_b[1] * p.b.vertices[tb[1]] +
                      s.bary_b[2] * p.b.vertices[tb[2]];
    EXPECT_LT((on_b - s.end).norm(), 1e-12);
  }
}

TEST(StrandGenerator, SameSeedSameStrandsOtherSeedOthers) {
  const Plates p = plates(0.01);
  StrandParams params;
  params.max_length = 0.02;
  const StrandGeneration a = generate_strands(p.a, p.b, params);
  const StrandGeneration b = generate_strands(p.a, p.b, params);
  params.seed = 2;
  const StrandGeneration c = generate_strands(p.a, p.b, params);
  ASSERT_EQ(a.strands.size(), b.strands.size());
  for (std::size_t i = 0; i < a.strands.size(); ++i) {
    EXPECT_EQ(a.strands[i].start, b.strands[i].start);
    EXPECT_EQ(a.strands[i].end, b.strands[i].end);
  }
  bool differs = a.strands.size() != c.strands.size();
  for (std::size_t i = 0; !differs && i < a.strands.size(); ++i) {
    differs = a.strands[i].start != c.strands[i].start;
  }
  EXPECT_TRUE(differs);
}

TEST(StrandGenerator, OnlyFacesThatFaceEachOtherAreUsed) {
  const Plates p = plates(0.01, false);  // B's normals point away from A
  StrandParams params;
  params.max_length = 0.02;
  EXPECT_TRUE(generate_strands(p.a, p.b, params).strands.empty());
  // Nor does A connect from its back: B below A.
  Plates q = plates(0.01);
  for (Vec3& x : q.b.vertices)
    x.y() = -0.01;
  EXPECT_TRUE(generate_strands(q.a, q.b, params).eligible_faces.empty());
}

TEST(StrandGenerator, DefaultMaxLengthIsTheCentreDistance) {
  const Plates p = plates(0.01);
  StrandParams params;  // max_length 0: eq. 6
  const StrandGeneration g = generate_strands(p.a, p.b, params);
  EXPECT_NEAR(g.max_length, centre_distance(p.a, p.b), 1e-15);
  EXPECT_NEAR(g.max_length, 0.01, 1e-12);  // both plates centred on the same axis
}

TEST(StrandGenerator, RejectsBadParameters) {
  const Plates p = plates(0.01);
  StrandParams params;
  params.segments = 0;
  EXPECT_THROW(generate_strands(p.a, p.b, params), std::invalid_argument);
  params.segments = 3;
  params.max_angle = 2;
  EXPECT_THROW(generate_strands(p.a, p.b, params), std::invalid_argument);
  params.max_angle = 0.3;
  params.strands_per_face = -1;
  EXPECT_THROW(generate_strands(p.a, p.b, params), std::invalid_argument);
}

}  // namespace
}  // namespace imasim::tissue
