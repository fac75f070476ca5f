#include "render/sphere_order.hpp"

#include <algorithm>
#include <cmath>

namespace imasim::render {

void SphereOrder::sort(const Spheres& spheres, const std::array<float, 3>& eye) {
  const std::size_t n = spheres.count();
  distance_.resize(n);
  float lo = 0, hi = 0;
  for (std::size_t i = 0; i < n; ++i) {
    float d2 = 0;
    for (std::size_t k = 0; k < 3; ++k) {
      const float c = spheres.centres[3 * i + k] - eye[k];
      d2 += c * c;
    }
    const float d = std::sqrt(d2);
    distance_[i] = d;
    lo = i == 0 ? d : std::min(lo, d);
    hi = i == 0 ? d : std::max(hi, d);
  }
  const float scale = hi > lo ? float(kBuckets - 1) / (hi - lo) : 0;
  bucket_.resize(n);
  bucket_start_.assign(kBuckets + 1, 0);
  for (std::size_t i = 0; i < n; ++i) {
    // Clamped: a non-finite position (never expected) must not index outside the buckets.
    const float b = std::clamp((distance_[i] - lo) * scale, 0.0f, float(kBuckets - 1));
    bucket_[i] = std::isfinite(b) ? std::uint32_t(b) : std::uint32_t(kBuckets - 1);
    ++bucket_start_[bucket_[i] + 1];
  }
  for (std::size_t b = 0; b < kBuckets; ++b)
    bucket_start_[b + 1] += bucket_start_[b];
  centres_.resize(3 * n);
  radii_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t j = bucket_start_[bucket_[i]]++;
    std::copy_n(spheres.centres.begin() + std::ptrdiff_t(3 * i), 3,
                centres_.begin() + std::ptrdiff_t(3 * j));
    radii_[j] = spheres.radii[i];
  }
}

}  // namespace imasim::render
