// The fat's draw order (render/sphere_order.hpp): a permutation of the spheres, centres and radii
// kept together, nearest the eye first to within one bucket's width, the strands' own order kept
// within a bucket; one sphere, or all at one distance, come out as they went in.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "render/sphere_order.hpp"

namespace imasim::render {
namespace {

float distance(const float* c, const std::array<float, 3>& eye) {
  return std::sqrt((c[0] - eye[0]) * (c[0] - eye[0]) + (c[1] - eye[1]) * (c[1] - eye[1]) +
                   (c[2] - eye[2]) * (c[2] - eye[2]));
}

TEST(SphereOrder, NearestFirstAsAPermutationWithinABucketsWidth) {
  std::mt19937 random(7);
  std::uniform_real_distribution<float> within(-0.05f, 0.05f);
  Spheres fat;
  for (int i = 0; i < 5000; ++i) {
    fat.centres.insert(fat.centres.end(), {within(random), within(random), within(random)});
    fat.radii.push_back(1e-4f * float(i + 1));  // each radius names its sphere
  }
  const std::array<float, 3> eye = {0.02f, -0.08f, 0.01f};
  SphereOrder order;
  order.sort(fat, eye);
  ASSERT_EQ(order.radii().size(), fat.count());
  ASSERT_EQ(order.centres().size(), fat.centres.size());
  float lo = 1e30f, hi = 0;
  for (std::size_t i = 0; i < fat.count(); ++i) {
    lo = std::min(lo, distance(&fat.centres[3 * i], eye));
    hi = std::max(hi, distance(&fat.centres[3 * i], eye));
  }
  const float bucket = (hi - lo) / float(SphereOrder::kBuckets - 1);
  std::vector<bool> seen(fat.count(), false);
  float previous = 0;
  std::size_t previous_index = 0;
  for (std::size_t j = 0; j < fat.count(); ++j) {
    const auto i = std::size_t(std::lround(order.radii()[j] / 1e-4f)) - 1;
    ASSERT_LT(i, fat.count());
    EXPECT_FALSE(seen[i]) << "sphere " << i << " twice";
    seen[i] = true;
    for (std::size_t k = 0; k < 3; ++k)
      EXPECT_EQ(order.centres()[3 * j + k], fat.centres[3 * i + k]) << "centre and radius apart";
    const float d = distance(&order.centres()[3 * j], eye);
    EXPECT_GE(d, previous - bucket * 1.001f) << "farther sphere before a nearer one at " << j;
    // Same bucket (clear of its edges, where rounding may differ): the strands' order stands.
    const float f = (d - lo) / bucket, g = (previous - lo) / bucket;
    const auto inside = [](float x) {
      return x - std::floor(x) > 0.01f && x - std::floor(x) < 0.99f;
    };
    if (j > 0 && std::floor(f) == std::floor(g) && inside(f) && inside(g)) {
      EXPECT_GT(i, previous_index);
    }
    previous = d;
    previous_index = i;
  }
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](bool s) { return s; }));
  const float nearest = distance(&order.centres()[0], eye);
  EXPECT_LE(nearest, lo + bucket);
}

TEST(SphereOrder, OneDistanceOrOneSphereKeepsTheOrder) {
  Spheres ring;
  for (int i = 0; i < 8; ++i) {
    const float a = float(i) * 0.785398f;
    ring.centres.insert(ring.centres.end(), {0.01f * std::cos(a), 0.01f * std::sin(a), 0});
    ring.radii.push_back(float(i));
  }
  SphereOrder order;
  order.sort(ring, {0, 0, 0});
  for (std::size_t j = 0; j < 8; ++j)
    EXPECT_EQ(order.radii()[j], float(j));
  Spheres none;
  order.sort(none, {0, 0, 0});
  EXPECT_TRUE(order.radii().empty());
  EXPECT_TRUE(order.centres().empty());
}

}  // namespace
}  // namespace imasim::render
