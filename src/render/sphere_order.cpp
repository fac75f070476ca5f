#include "render/sphere_order.hpp"

#include <algorithm>
#include <cmath>

#include "render/sphere_sprite.hpp"

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

void SphereOrder::split_sprites(const Camera& camera, float width, float height,
                                float max_sprite_px) {
  near_centres_.clear();
  near_radii_.clear();
  std::size_t kept = 0;
  for (std::size_t i = 0; i < radii_.size(); ++i) {
    const std::array<float, 3> c{centres_[3 * i], centres_[3 * i + 1], centres_[3 * i + 2]};
    const SpriteBounds b = sphere_sprite(camera, c, radii_[i], width, height);
    if (b.kind == SpriteBounds::Kind::outside) continue;
    if (b.kind == SpriteBounds::Kind::at_eye || b.size_px > max_sprite_px) {
      near_centres_.insert(near_centres_.end(), c.begin(), c.end());
      near_radii_.push_back(radii_[i]);
      continue;
    }
    std::copy(c.begin(), c.end(), centres_.begin() + std::ptrdiff_t(3 * kept));
    radii_[kept++] = radii_[i];
  }
  centres_.resize(3 * kept);
  radii_.resize(kept);
}

}  // namespace imasim::render
