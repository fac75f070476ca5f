#pragma once
// The fat's spheres nearest the eye first, for drawing. The impostors' shader discards the
// square's corners, but llvmpipe still tests depth before shading (and writes it after): a
// sphere hidden behind one drawn earlier costs no shading. Drawn in the strands' own order, the
// fat seen edge on through the endoscope was shaded several times over (docs/rendering.md).
#include <array>
#include <cstdint>
#include <vector>

#include "render/render_frame.hpp"

namespace imasim::render {

// A counting sort into kBuckets buckets of distance between the nearest and the farthest
// sphere: linear in the spheres, nearest first up to a bucket's width, and within a bucket the
// strands' own order (neighbours on screen stay neighbours). Reuses its buffers frame to frame.
class SphereOrder {
 public:
  static constexpr std::size_t kBuckets = 1024;

  // Fills centres() and radii() with `spheres` reordered for an eye at `eye` (unit: m).
  void sort(const Spheres& spheres, const std::array<float, 3>& eye);
  const std::vector<float>& centres() const { return centres_; }  // x, y, z per sphere
  const std::vector<float>& radii() const { return radii_; }

 private:
  std::vector<float> distance_;
  std::vector<std::uint32_t> bucket_, bucket_start_;
  std::vector<float> centres_, radii_;
};

}  // namespace imasim::render
