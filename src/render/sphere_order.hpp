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
  // Then, for a viewport of width x height pixels: drops the spheres wholly outside the view,
  // and moves those a point sprite cannot draw (reaching the eye's plane, or needing a sprite
  // wider than max_sprite_px) to near_centres() and near_radii(); both keep nearest first.
  void split_sprites(const Camera& camera, float width, float height, float max_sprite_px);
  const std::vector<float>& centres() const { return centres_; }  // x, y, z per sphere
  const std::vector<float>& radii() const { return radii_; }
  const std::vector<float>& near_centres() const { return near_centres_; }
  const std::vector<float>& near_radii() const { return near_radii_; }

 private:
  std::vector<float> distance_;
  std::vector<std::uint32_t> bucket_, bucket_start_;
  std::vector<float> centres_, radii_, near_centres_, near_radii_;
};

}  // namespace imasim::render
