#pragma once
// Where a sphere's outline lies on the screen, for drawing the fat as point sprites
// (sphere_shaders.hpp computes the same bounds on the GPU). Along each image axis the outline
// is bounded by the two planes through the eye tangent to the sphere: in the plane of that axis
// and the view axis, a centre at lateral offset x and depth d, at distance L = sqrt(x^2 + d^2)
// with t = sqrt(L^2 - r^2), has tangents of slope (x t -+ d r) / (d t +- x r). Both
// denominators are positive while the sphere is wholly in front of the eye (d > r).
#include <array>

#include "render/render_frame.hpp"

namespace imasim::render {

struct SpriteBounds {
  enum class Kind {
    sprite,   // drawn as a point of size_px about the centre (ndc)
    outside,  // wholly outside the view: not drawn
    at_eye,   // reaches the eye's plane: its outline is unbounded
  };
  Kind kind = Kind::outside;
  // The sprite's centre in normalised device coordinates, kept just inside the view so that
  // the rasteriser does not drop the point, and its side, long enough to reach the outline's
  // far side from there (unit: pixel).
  std::array<float, 2> centre_ndc{};
  float size_px = 0;
};

// A sphere of `radius` about `centre` (world, unit: m) seen by `camera` in a viewport of
// width x height pixels.
SpriteBounds sphere_sprite(const Camera& camera, const std::array<float, 3>& centre, float radius,
                           float width, float height);

}  // namespace imasim::render
